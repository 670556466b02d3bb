// A model with two grids: spiral stairs (a screw 1-grid) and, above and beside them, a fence (a
// translation 1-grid). Each grid's pieces hold the whole model, so resize and generate change one
// grid at a time and leave the other part as the exemplar has it.

#include "synthesis/grid_resize.h"
#include "synthesis/variants.h"

#include "assets/generator/asset.h"
#include "geometry/submesh.h"
#include "grammar/grammar_file.h"
#include "support/asset_grammar.h"
#include "support/cli_run.h"
#include "support/mesh_distance.h"
#include "support/shapes.h"

#include <catch2/catch.hpp>

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
  for (std::size_t i = 0; i < 2; ++i) {
    const dg::GridDirection& d = g.grammar.grids[i].rule.directions.front();
    (std::abs(d.direction.x()) > 0.99 ? g.fence_grid : g.stairs_grid) = i;
  }
  REQUIRE(g.fence_grid != g.stairs_grid);
  REQUIRE(g.grammar.grids[g.fence_grid].rule.directions.front().count == 4);
  return g;
}

}  // namespace

TEST_CASE("two grids: resizing one leaves the other part as it was", "[synthesis][grid]") {
  const TwoGrids g = two_grids();
  const dg::GridWithPieces& grid = g.grammar.grids[g.fence_grid];
  const dg::TriangleMesh resized = dg::resize_grid(grid.rule, grid.pieces, {6}, g.grammar.eps);
  CHECK(dg::test::hausdorff_distance(part(resized, true), fence(6)) < 1e-3 * g.grammar.eps);
  CHECK(dg::test::hausdorff_distance(part(resized, false), stairs()) < 1e-3 * g.grammar.eps);
}

TEST_CASE("two grids: each variant resizes one grid, drawn at random, and the other keeps its counts", "[synthesis][variants]") {
  const TwoGrids g = two_grids();
  std::vector<std::vector<int>> exemplar_counts;
  for (const dg::GridWithPieces& grid : g.grammar.grids) exemplar_counts.push_back({grid.rule.directions.front().count});
  std::set<std::size_t> resized_grids;
  std::optional<dg::VariantPlan> fence_plan;
  for (std::uint64_t i = 0; i < 16; ++i) {
    const dg::VariantPlan plan = dg::plan_variant(g.grammar, 7, i);
    REQUIRE(plan.grid_counts.size() == 2);
    resized_grids.insert(plan.grid);
    CHECK(plan.grid_counts[plan.grid] != exemplar_counts[plan.grid]);
    CHECK(plan.grid_counts[1 - plan.grid] == exemplar_counts[1 - plan.grid]);
    if (plan.grid == g.fence_grid && !fence_plan) fence_plan = plan;
  }
  CHECK(resized_grids.size() == 2);
  REQUIRE(fence_plan);
  const dg::Variant variant = dg::build_variant(g.grammar, *fence_plan);
  CHECK(variant.changed);
  CHECK(dg::test::hausdorff_distance(part(variant.mesh, true), fence(fence_plan->grid_counts[g.fence_grid].front())) <
        1e-3 * g.grammar.eps);
  CHECK(dg::test::hausdorff_distance(part(variant.mesh, false), stairs()) < 1e-3 * g.grammar.eps);
}

TEST_CASE("resize CLI: one grid per run of a grammar with two", "[synthesis][grid][cli]") {
  const TwoGrids g = two_grids();
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-two-grids");
  dg::write_grammar(folder / "two.grammar.json", g.grammar);
  const std::string fence_name = g.grammar.grids[g.fence_grid].rule.name;
  const std::string stairs_name = g.grammar.grids[g.stairs_grid].rule.name;
  const dg::test::CliRun both = dg::test::run_cli(
      "resize " + (folder / "two.grammar.json").string() + " --grid " + fence_name + "=6 --grid " + stairs_name + "=12 -o " +
          (folder / "both.obj").string(),
      folder);
  CHECK(both.status == 2);
  CHECK_THAT(both.output, Catch::Contains("one grid at a time"));
  CHECK_FALSE(std::filesystem::exists(folder / "both.obj"));
  const dg::test::CliRun one =
      dg::test::run_cli("resize " + (folder / "two.grammar.json").string() + " --grid " + fence_name + "=6 -q -o " +
                            (folder / "one.obj").string(),
                        folder);
  CHECK(one.status == 0);
  CHECK(std::filesystem::exists(folder / "one.obj"));
}
