// A model with two grids: spiral stairs (a screw 1-grid) and, above and beside them, a fence (a
// translation 1-grid). Each grid's pieces hold the whole model: resizing one grid leaves the other
// part as the exemplar has it, and resizing both (resize, generate) cuts the second grid again
// from the first result.

#include "synthesis/grid_resize.h"
#include "synthesis/several_grids.h"
#include "synthesis/variants.h"

#include "assets/generator/asset.h"
#include "geometry/errors.h"
#include "geometry/model_io.h"
#include "geometry/submesh.h"
#include "geometry/topology.h"
#include "grammar/grammar_file.h"
#include "grammar/grid_cut.h"
#include "support/asset_grammar.h"
#include "support/cli_run.h"
#include "support/mesh_distance.h"
#include "support/shapes.h"

#include <catch2/catch.hpp>

#include <numbers>
#include <optional>
#include <set>

namespace {

// Where the fence stands: beyond the stairs along x and above their top (z 3.16), so the
// stairs' cut planes (horizontal) and the fence's (across x) each miss the other part.
const dg::Vec3 kFenceOffset(2.0, 0.0, 3.5);

dg::TriangleMesh fence(int units) {
  return dg::transformed(dg::assets::make_asset("fence", {{"n", units}}).mesh, dg::RigidTransform{dg::Mat3::Identity(), kFenceOffset});
}

dg::TriangleMesh stairs() { return dg::assets::make_asset("spiral_stairs", {}).mesh; }

// The triangles of `mesh` whose centroid lies above (`upper`) or below z = 3.3: fence or stairs.
dg::TriangleMesh part(const dg::TriangleMesh& mesh, bool upper) {
  std::vector<std::size_t> triangles;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const dg::Triangle& t = mesh.triangles[i];
    const double z = (mesh.positions[t[0]].z() + mesh.positions[t[1]].z() + mesh.positions[t[2]].z()) / 3.0;
    if ((z > 3.3) == upper) triangles.push_back(i);
  }
  return dg::submesh(mesh, triangles);
}

struct TwoGrids {
  dg::ShapeGrammar grammar;
  std::size_t fence_grid = 0, stairs_grid = 0;
};

TwoGrids two_grids() {
  dg::Model model;
  model.mesh = stairs();
  dg::test::append(model.mesh, fence(4));
  TwoGrids g{dg::test::model_grammar(std::move(model), false)};
  REQUIRE(g.grammar.grids.size() == 2);
  // The stairs turn (a screw); the fence only slides along x.
  int screws = 0;
  for (std::size_t i = 0; i < 2; ++i) {
    const dg::GridDirection& d = g.grammar.grids[i].rule.directions.front();
    const bool screw = d.motion.angle() > 0.1;
    screws += screw ? 1 : 0;
    if (!screw) REQUIRE(std::abs(d.direction.x()) > 0.99);
    (screw ? g.stairs_grid : g.fence_grid) = i;
  }
  REQUIRE(screws == 1);
  REQUIRE(g.grammar.grids[g.fence_grid].rule.directions.front().count == 4);
  return g;
}

// The generator's stairs with `extra` steps more than the exemplar's 12 and fence(units) where
// that puts it: the fence lies in the stairs' tail piece, so it turns and rises with the last
// step (12 steps per turn, rise 0.18).
dg::TriangleMesh stairs_with_fence(int extra, int units) {
  dg::TriangleMesh expected = dg::assets::make_asset("spiral_stairs", {{"steps", 12 + extra}}).mesh;
  const dg::RigidTransform screw{dg::Mat3(Eigen::AngleAxisd(extra * std::numbers::pi / 6.0, dg::Vec3::UnitZ())),
                                 dg::Vec3(0.0, 0.0, 0.18 * extra)};
  dg::test::append(expected, dg::transformed(fence(units), screw));
  return expected;
}

int stairs_count(const TwoGrids& g) { return g.grammar.grids[g.stairs_grid].rule.directions.front().count; }

}  // namespace

TEST_CASE("two grids: resizing one leaves the other part as it was", "[synthesis][grid]") {
  const TwoGrids g = two_grids();
  const dg::GridWithPieces& grid = g.grammar.grids[g.fence_grid];
  const dg::TriangleMesh resized = dg::resize_grid(grid.rule, grid.pieces, {6}, g.grammar.eps);
  CHECK(dg::test::hausdorff_distance(part(resized, true), fence(6)) < 1e-3 * g.grammar.eps);
  CHECK(dg::test::hausdorff_distance(part(resized, false), stairs()) < 1e-3 * g.grammar.eps);
}

TEST_CASE("two grids: each variant resizes both", "[synthesis][variants]") {
  const TwoGrids g = two_grids();
  std::set<int> fence_counts, stairs_counts;
  for (std::uint64_t i = 0; i < 4; ++i) {
    const dg::VariantPlan plan = dg::plan_variant(g.grammar, 7, i);
    REQUIRE(plan.grid_counts.size() == 2);
    const dg::Variant variant = dg::build_variant(g.grammar, plan);
    CHECK(variant.changed);
    CHECK(variant.one_grid_only.empty());
    CHECK(variant.grid_counts == plan.grid_counts);
    const int fence_units = plan.grid_counts[g.fence_grid].front(), steps = plan.grid_counts[g.stairs_grid].front();
    fence_counts.insert(fence_units);
    stairs_counts.insert(steps);
    CHECK(dg::test::hausdorff_distance(variant.mesh, stairs_with_fence(steps - stairs_count(g), fence_units)) < g.grammar.eps);
  }
  CHECK(fence_counts.size() > 1);
  CHECK(stairs_counts.size() > 1);
}

TEST_CASE("two grids resized in one run: the stairs grow and the fence on their tail grows with them", "[synthesis][grid]") {
  const TwoGrids g = two_grids();
  const int steps = stairs_count(g);  // the top steps lie in the tail piece with the fence
  for (const std::vector<dg::GridResize>& resizes :
       {std::vector<dg::GridResize>{{g.fence_grid, {6}}, {g.stairs_grid, {steps + 2}}},
        std::vector<dg::GridResize>{{g.stairs_grid, {steps + 2}}, {g.fence_grid, {6}}}}) {
    const dg::TriangleMesh resized = dg::resize_grids(g.grammar, resizes);
    const dg::TriangleMesh expected = stairs_with_fence(2, 6);
    CHECK(dg::is_closed_and_oriented(resized));
    CHECK(dg::test::hausdorff_distance(resized, expected) < g.grammar.eps);
    CHECK(resized.area() == Approx(expected.area()).epsilon(1e-3));
  }
  // Fewer steps and a shorter fence.
  const dg::TriangleMesh smaller = dg::resize_grids(g.grammar, {{g.stairs_grid, {steps - 3}}, {g.fence_grid, {3}}});
  CHECK(dg::is_closed_and_oriented(smaller));
  CHECK(dg::test::hausdorff_distance(smaller, stairs_with_fence(-3, 3)) < g.grammar.eps);
  // One grid: the same mesh as resize_grid; the exemplar's counts for the other change nothing.
  const dg::GridWithPieces& fence_grid = g.grammar.grids[g.fence_grid];
  const dg::TriangleMesh alone = dg::resize_grid(fence_grid.rule, fence_grid.pieces, {6}, g.grammar.eps);
  for (const dg::TriangleMesh& same : {dg::resize_grids(g.grammar, {{g.fence_grid, {6}}}),
                                       dg::resize_grids(g.grammar, {{g.fence_grid, {6}}, {g.stairs_grid, {steps}}})}) {
    CHECK(same.positions == alone.positions);
    CHECK(same.triangles == alone.triangles);
  }
  CHECK_THROWS_AS(dg::resize_grids(g.grammar, {{g.fence_grid, {6}}, {g.fence_grid, {5}}}), dg::InputError);
  CHECK_THROWS_AS(dg::resize_grids(g.grammar, {{g.fence_grid, {6}}, {g.stairs_grid, {-1}}}), dg::InputError);
}

TEST_CASE("two grids that overlap are not resized together", "[synthesis][grid]") {
  // The fence's pieces moved down among the stairs' steps: what a resize of the fence adds or
  // moves then lies in the stairs' repeated units, which their resize would copy or drop.
  TwoGrids g = two_grids();
  const dg::RigidTransform down{dg::Mat3::Identity(), dg::Vec3(0.0, 0.0, -3.0)};
  for (dg::GridPiece& piece : g.grammar.grids[g.fence_grid].pieces) piece.mesh = dg::transformed(piece.mesh, down);
  try {
    (void)dg::resize_grids(g.grammar, {{g.fence_grid, {6}}, {g.stairs_grid, {stairs_count(g) + 2}}});
    FAIL("resize_grids accepted overlapping grids");
  } catch (const dg::InputError& e) {
    const std::string message = e.what();
    CHECK_THAT(message, Catch::Contains("overlap") && Catch::Contains(g.grammar.grids[0].rule.name) &&
                            Catch::Contains(g.grammar.grids[1].rule.name));
    CHECK_THAT(message, Catch::Contains("resize one, analyze the result, then resize the other"));
  }
  // Resizing the fence alone stays possible.
  CHECK_NOTHROW(dg::resize_grids(g.grammar, {{g.fence_grid, {6}}, {g.stairs_grid, {stairs_count(g)}}}));
  // A variant then resizes its drawn grid only and says why; the other keeps the exemplar's counts.
  std::set<std::size_t> resized;
  for (std::uint64_t i = 0; i < 8; ++i) {
    const dg::VariantPlan plan = dg::plan_variant(g.grammar, 3, i);
    const dg::Variant variant = dg::build_variant(g.grammar, plan);
    CHECK_THAT(variant.one_grid_only, Catch::Contains("overlap"));
    const std::size_t other = 1 - plan.grid;
    CHECK(variant.grid_counts[plan.grid] == plan.grid_counts[plan.grid]);
    CHECK(variant.grid_counts[other] == std::vector<int>{g.grammar.grids[other].rule.directions.front().count});
    CHECK(variant.changed);
    resized.insert(plan.grid);
  }
  CHECK(resized.size() == 2);
}

TEST_CASE("resize CLI: several grids in one run", "[synthesis][grid][cli]") {
  const TwoGrids g = two_grids();
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-two-grids");
  dg::write_grammar(folder / "two.grammar.json", g.grammar);
  const std::string grammar = (folder / "two.grammar.json").string();
  const std::string fence_name = g.grammar.grids[g.fence_grid].rule.name;
  const std::string stairs_name = g.grammar.grids[g.stairs_grid].rule.name;
  const dg::test::CliRun both = dg::test::run_cli(
      "resize " + grammar + " --grid " + fence_name + "=6 --grid " + stairs_name + "=" + std::to_string(stairs_count(g) + 2) +
          " -q -o " + (folder / "both.ply").string(),
      folder);
  CHECK(both.status == 0);
  REQUIRE(std::filesystem::exists(folder / "both.ply"));
  const dg::TriangleMesh written = dg::read_model(folder / "both.ply").mesh;
  CHECK(dg::test::hausdorff_distance(written, stairs_with_fence(2, 6)) < g.grammar.eps);
  const dg::test::CliRun twice = dg::test::run_cli(
      "resize " + grammar + " --grid " + fence_name + "=6 --grid " + fence_name + "=5 -o " + (folder / "twice.obj").string(),
      folder);
  CHECK(twice.status == 2);
  CHECK_THAT(twice.output, Catch::Contains("given twice"));
  CHECK_FALSE(std::filesystem::exists(folder / "twice.obj"));
}

namespace {

// The grammar of fence(n) with a gate and `after_gate` inner posts after it: one grid per
// stretch (the one with more units is grid1).
struct GatedFence {
  dg::ShapeGrammar grammar;
  int n = 0, after_gate = 0;
  std::size_t first = 0, second = 1;  // the grids of the stretches before and after the gate
};

GatedFence gated_fence(int n, int after_gate) {
  GatedFence g{dg::test::asset_grammar("fence", {{"n", n}, {"after_gate", after_gate}}, false), n, after_gate};
  REQUIRE(g.grammar.grids.size() == 2);
  const dg::GridDirection& grid1 = g.grammar.grids[0].rule.directions.front();
  if (grid1.direction.x() * (grid1.cut + 0.5 * grid1.pitch) > 0.5 * (n + 1) * 2.0) std::swap(g.first, g.second);
  REQUIRE(g.grammar.grids[g.first].rule.directions.front().count == n);
  REQUIRE(g.grammar.grids[g.second].rule.directions.front().count == after_gate);
  return g;
}

dg::TriangleMesh gated(int n, int after_gate) {
  return dg::assets::make_asset("fence", {{"n", n}, {"after_gate", after_gate}}).mesh;
}

}  // namespace

TEST_CASE("fence with a gate: both stretches resized in one run, in the order that keeps each change in a stored piece",
          "[synthesis][grid]") {
  // Growing the first stretch moves the gate and the whole second stretch, so the second is
  // resized first whatever order the resizes are given in (grid1 is either).
  for (const GatedFence& g : {gated_fence(3, 4), gated_fence(4, 3)}) {
    for (const auto& [first, second] : {std::pair{5, 6}, std::pair{2, 7}, std::pair{6, 1}}) {
      INFO("fence " << g.n << ", gate, " << g.after_gate << " resized to " << first << " and " << second);
      const dg::TriangleMesh expected = gated(first, second);
      for (const std::vector<dg::GridResize>& resizes :
           {std::vector<dg::GridResize>{{g.first, {first}}, {g.second, {second}}},
            std::vector<dg::GridResize>{{g.second, {second}}, {g.first, {first}}}}) {
        const dg::TriangleMesh resized = dg::resize_grids(g.grammar, resizes);
        CHECK(dg::is_closed_and_oriented(resized));
        CHECK(dg::test::hausdorff_distance(resized, expected) < 1e-3 * g.grammar.eps);
        CHECK(resized.area() == Approx(expected.area()).epsilon(1e-6));
      }
    }
    // Each stretch alone.
    CHECK(dg::test::hausdorff_distance(dg::resize_grids(g.grammar, {{g.first, {7}}}), gated(7, g.after_gate)) <
          1e-3 * g.grammar.eps);
    CHECK(dg::test::hausdorff_distance(dg::resize_grids(g.grammar, {{g.second, {9}}}), gated(g.n, 9)) < 1e-3 * g.grammar.eps);
  }
}

TEST_CASE("fence with a gate: each variant draws and resizes both stretches", "[synthesis][variants]") {
  const GatedFence g = gated_fence(4, 3);
  std::set<std::pair<int, int>> drawn;
  for (std::uint64_t i = 0; i < 4; ++i) {
    const dg::VariantPlan plan = dg::plan_variant(g.grammar, 11, i);
    REQUIRE(plan.grid_counts.size() == 2);
    const dg::Variant variant = dg::build_variant(g.grammar, plan);
    CHECK(variant.one_grid_only.empty());
    CHECK(variant.grid_counts == plan.grid_counts);
    const int first = plan.grid_counts[g.first].front(), second = plan.grid_counts[g.second].front();
    drawn.emplace(first, second);
    CHECK(dg::test::hausdorff_distance(variant.mesh, gated(first, second)) < g.grammar.eps);
  }
  CHECK(drawn.size() > 1);
}

namespace {

// Two facade(columns x 3) wings on either side of a plain 6 m tower, 18 m high: the left wing's
// columns and the floors of both form a 2-grid, the right wing's columns a further 1-grid.
dg::TriangleMesh winged(int left_columns, int right_columns, int rows, double tower_height) {
  const double pitch = 3.0;  // the facade's default column pitch
  dg::TriangleMesh mesh = dg::assets::make_asset("facade", {{"columns", left_columns}, {"rows", rows}}).mesh;
  const double tower = 2.0 + left_columns * pitch;  // the wall's right end (1 m margins)
  dg::test::append(mesh, dg::test::make_box(dg::Vec3(tower, -0.6, 0.0), dg::Vec3(tower + 6.0, 0.6, tower_height)));
  dg::test::append(mesh, dg::transformed(dg::assets::make_asset("facade", {{"columns", right_columns}, {"rows", rows}}).mesh,
                                         dg::RigidTransform{dg::Mat3::Identity(), dg::Vec3(tower + 6.0, 0.0, 0.0)}));
  return mesh;
}

}  // namespace

TEST_CASE("two facade wings beside a tower: a resize that keeps the floors widens both wings in one run",
          "[synthesis][grid]") {
  dg::Model model;
  model.mesh = winged(3, 3, 3, 18.0);
  const dg::ShapeGrammar grammar = dg::test::model_grammar(std::move(model), false);
  REQUIRE(grammar.grids.size() == 2);
  REQUIRE(grammar.grids[0].rule.directions.size() == 2);
  REQUIRE(grammar.grids[1].rule.directions.size() == 1);
  // grid1: columns of one wing (x) and floors (z); grid2: the other wing's columns.
  const std::size_t columns = std::abs(grammar.grids[0].rule.directions[0].direction.x()) > 0.99 ? 0 : 1;
  const dg::GridDirection& grid1_columns = grammar.grids[0].rule.directions[columns];
  REQUIRE(std::abs(grammar.grids[1].rule.directions[0].direction.x()) > 0.99);
  CHECK(grid1_columns.count == 3);
  CHECK(grammar.grids[0].rule.directions[1 - columns].count == 3);
  CHECK(grammar.grids[1].rule.directions[0].count == 3);
  const bool grid1_left = grid1_columns.direction.x() * (grid1_columns.cut + 0.5 * grid1_columns.pitch) < 13.0;
  auto grid1_counts = [&](int wing_columns, int floors) {
    return columns == 0 ? std::vector<int>{wing_columns, floors} : std::vector<int>{floors, wing_columns};
  };
  // Five columns in grid1's wing and six in the other, the floors kept: one run.
  const dg::TriangleMesh wider = dg::resize_grids(grammar, {{0, grid1_counts(5, 3)}, {1, {6}}});
  const dg::TriangleMesh expected = grid1_left ? winged(5, 6, 3, 18.0) : winged(6, 5, 3, 18.0);
  CHECK(dg::test::hausdorff_distance(wider, expected) < 1e-3 * grammar.eps);
  CHECK(wider.area() == Approx(expected.area()).epsilon(1e-6));
  // Two more floors run through both wings and the tower.
  const dg::TriangleMesh taller = dg::resize_grids(grammar, {{0, grid1_counts(3, 5)}});
  CHECK(dg::test::hausdorff_distance(taller, winged(3, 3, 5, 24.0)) < 1e-3 * grammar.eps);
  // More floors and a wider second wing: the floors' planes cross the second wing's units, and
  // its units cross every floor, so neither order keeps a change in one stored piece.
  CHECK_THROWS_WITH(dg::resize_grids(grammar, {{0, grid1_counts(3, 5)}, {1, {6}}}), Catch::Contains("overlap"));
}

TEST_CASE("a grid of bays and the grid of the columns it groups are not resized together", "[synthesis][grid]") {
  dg::Model model;
  model.mesh = dg::test::pilaster_facade(9, 2);
  const dg::ShapeGrammar grammar = dg::test::model_grammar(std::move(model), false);
  REQUIRE(grammar.grids.size() == 2);
  const std::optional<dg::GroupedUnits> grouped = dg::grouped_units(grammar.grids[1].rule, grammar.grids[0].rule);
  REQUIRE(grouped.has_value());
  CHECK(grouped->factor == 3);
  CHECK_FALSE(dg::grouped_units(grammar.grids[0].rule, grammar.grids[1].rule).has_value());
  std::vector<int> columns = dg::exemplar_counts(grammar.grids[0].rule), bays = dg::exemplar_counts(grammar.grids[1].rule);
  columns[grouped->direction] += 1;
  bays[grouped->direction] += 1;
  try {
    (void)dg::resize_grids(grammar, {{0, columns}, {1, bays}});
    FAIL("resize_grids accepted a grid of bays with the grid of its columns");
  } catch (const dg::InputError& e) {
    CHECK_THAT(std::string(e.what()), Catch::Contains("grid2 groups the units of grid1 (3 of them along direction 1 make one)"));
  }
  // Each alone resizes; the bays' resize is the facade of 12 columns.
  CHECK_NOTHROW(dg::resize_grids(grammar, {{0, columns}}));
  const dg::TriangleMesh wider = dg::resize_grids(grammar, {{1, bays}});
  CHECK(dg::test::hausdorff_distance(wider, dg::test::pilaster_facade(12, 2)) < 1e-3 * grammar.eps);
}
