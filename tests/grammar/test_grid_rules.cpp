#include "grammar/grid_rules.h"
#include "grammar/grid_cut.h"

#include "assets/generator/asset.h"
#include "geometry/polygon_triangulation.h"
#include "geometry/submesh.h"
#include "geometry/topology.h"
#include "grammar/grammar_file.h"
#include "synthesis/grid_resize.h"
#include "support/asset_grammar.h"
#include "support/cli_run.h"
#include "support/corpus.h"
#include "support/mesh_distance.h"
#include "support/shapes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <set>
#include <utility>
#include <vector>

using dg::Vec3;

namespace {

struct Analysis {
  dg::PreparedModel prepared;
  dg::SymmetryResult symmetries;
  std::vector<dg::GridRule> grids;
};

Analysis analyze_asset(const std::string& name, const nlohmann::json& params) {
  dg::Model model;
  model.mesh = dg::assets::make_asset(name, params).mesh;
  Analysis a{dg::prepare_model(std::move(model)), {}, {}};
  a.symmetries = dg::detect_symmetries(a.prepared);
  a.grids = dg::find_grids(a.prepared, a.symmetries);
  return a;
}

// The grids of a prepared model, from its detected symmetries.
std::vector<dg::GridRule> grids_of(const dg::PreparedModel& prepared) {
  return dg::find_grids(prepared, dg::detect_symmetries(prepared));
}

// A shape built in code, prepared, with its only grid (the test stops when it has not exactly
// one) and that grid's pieces.
struct OneGrid {
  dg::PreparedModel prepared;
  dg::GridRule grid;
  std::vector<dg::GridPiece> pieces;
};

OneGrid one_grid(dg::TriangleMesh mesh) {
  dg::Model model;
  model.mesh = std::move(mesh);
  OneGrid one{dg::prepare_model(std::move(model)), {}, {}};
  std::vector<dg::GridRule> grids = grids_of(one.prepared);
  REQUIRE(grids.size() == 1);
  one.grid = std::move(grids[0]);
  one.pieces = dg::cut_grid_pieces(one.prepared.model.mesh, one.grid, one.prepared.surface.eps());
  return one;
}

// `one`'s grid resized to n units in direction `along`, the other directions at the exemplar's
// counts.
dg::TriangleMesh resized_along(const OneGrid& one, std::size_t along, int n) {
  std::vector<int> counts = dg::exemplar_counts(one.grid);
  counts[along] = n;
  return dg::resize_grid(one.grid, one.pieces, counts, one.prepared.surface.eps());
}

// The grids of the generator's model turned by general_rotation() about the origin.
std::vector<dg::GridRule> turned_grids(const std::string& name, const nlohmann::json& params) {
  dg::Model turned;
  turned.mesh = dg::assets::make_asset(name, params).mesh;
  dg::test::turn_generally(turned.mesh);
  const dg::PreparedModel prepared = dg::prepare_model(std::move(turned));
  return grids_of(prepared);
}

// The direction of `grid` whose translation is +-t, or null.
const dg::GridDirection* direction_along(const dg::GridRule& grid, const Vec3& t) {
  for (const auto& d : grid.directions)
    if ((d.translation - t).norm() < 1e-6 || (d.translation + t).norm() < 1e-6) return &d;
  return nullptr;
}

}  // namespace

TEST_CASE("fence(n): a 1-grid along the post pitch whose count is the number of inner posts", "[grammar][grid]") {
  for (int n : {4, 9}) {
    const Analysis a = analyze_asset("fence", {{"n", n}});
    REQUIRE(a.grids.size() == 1);
    REQUIRE(a.grids[0].directions.size() == 1);
    const dg::GridDirection* along = direction_along(a.grids[0], Vec3(2.0, 0, 0));
    REQUIRE(along != nullptr);
    CHECK(along->count == n);  // ground truth: count = inner posts (assets/README.md)
  }
}

TEST_CASE("fence with a gate: one 1-grid per stretch, each counting its own inner posts", "[grammar][grid]") {
  for (const auto& [n, after_gate] : {std::pair{3, 4}, std::pair{5, 2}}) {
    INFO("fence " << n << ", gate, " << after_gate);
    const nlohmann::json params = {{"n", n}, {"after_gate", after_gate}};
    const nlohmann::json truth = dg::assets::make_asset("fence", params).ground_truth;
    const Analysis a = analyze_asset("fence", params);
    REQUIRE(a.grids.size() == 2);
    // Ground truth (assets/README.md): the first stretch's end posts stand at x = 0 and
    // (n + 1) pitch, the second's from (n + 2.5) pitch on; each grid's planes lie in one stretch.
    const double pitch = 2.0, gate_post = (n + 1) * pitch, second_start = gate_post + 1.5 * pitch;
    std::map<int, int> count_by_stretch;
    for (const dg::GridRule& grid : a.grids) {
      REQUIRE(grid.directions.size() == 1);
      const dg::GridDirection* along = direction_along(grid, Vec3(pitch, 0, 0));
      REQUIRE(along != nullptr);
      const double first = along->direction.x() > 0 ? along->cut : -along->cut - along->count * pitch;
      const double last = first + along->count * pitch;
      const int stretch = last <= gate_post ? 0 : first >= second_start ? 1 : -1;
      CHECK(stretch >= 0);
      count_by_stretch[stretch] = along->count;
    }
    CHECK(count_by_stretch == std::map<int, int>{{0, truth["repetitions"][0]["count"].get<int>()},
                                                 {1, truth["repetitions"][1]["count"].get<int>()}});
    CHECK(count_by_stretch[0] == n);
    CHECK(count_by_stretch[1] == after_gate);
  }
}

namespace {

// Connected components of `mesh` with exactly `size` triangles.
std::size_t components_of_size(const dg::TriangleMesh& mesh, std::size_t size) {
  std::size_t count = 0;
  const std::vector<std::uint32_t> component = dg::triangle_components(mesh, &count);
  std::vector<std::size_t> sizes(count, 0);
  for (std::uint32_t c : component) ++sizes[c];
  return static_cast<std::size_t>(std::count(sizes.begin(), sizes.end(), size));
}

// Bounding boxes of the connected components of `mesh`.
std::vector<dg::BoundingBox> component_boxes(const dg::TriangleMesh& mesh) {
  std::size_t count = 0;
  const std::vector<std::uint32_t> component = dg::triangle_components(mesh, &count);
  std::vector<dg::BoundingBox> boxes(count);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (const Vec3& corner : mesh.corners(t)) boxes[component[t]].add(corner);
  return boxes;
}

// Connected components of `mesh` whose bounding box measures `size` (within 1e-6).
std::size_t components_measuring(const dg::TriangleMesh& mesh, const Vec3& size) {
  const std::vector<dg::BoundingBox> boxes = component_boxes(mesh);
  return static_cast<std::size_t>(
      std::count_if(boxes.begin(), boxes.end(), [&](const dg::BoundingBox& b) { return (b.size() - size).norm() < 1e-6; }));
}

// Connected components of `mesh` narrower than 0.05 along x (the lockers' handles).
std::size_t narrow_components(const dg::TriangleMesh& mesh) {
  const std::vector<dg::BoundingBox> boxes = component_boxes(mesh);
  return static_cast<std::size_t>(
      std::count_if(boxes.begin(), boxes.end(), [](const dg::BoundingBox& b) { return b.size().x() < 0.05; }));
}

// `lockers` touching boxes 0.6 wide in a row along x, each a closed box with a handle near its
// right side.
dg::TriangleMesh lockers(int count) {
  dg::TriangleMesh mesh;
  for (int i = 0; i < count; ++i) {
    const double x = 0.6 * i;
    dg::test::append(mesh, dg::test::make_box(Vec3(x, -0.25, 0.0), Vec3(x + 0.6, 0.25, 2.0)));
    dg::test::append(mesh, dg::test::make_box(Vec3(x + 0.485, -0.29, 0.9), Vec3(x + 0.515, -0.25, 1.1)));
  }
  return mesh;
}

}  // namespace

TEST_CASE("a row of touching lockers: one unit per locker, one of them split between the ends", "[grammar][grid]") {
  // Planes may not cut where the lockers meet (faces lie there), so they cut through the lockers;
  // the part before the first plane and the part after the last make one locker together.
  const OneGrid one = one_grid(lockers(5));
  const dg::GridDirection* row = direction_along(one.grid, Vec3(0.6, 0, 0));
  REQUIRE(row != nullptr);
  CHECK(row->count == 5);
  CHECK(row->head_units == 1);
  CHECK(row->split_unit);
  for (int n : {1, 3, 5, 8}) {
    INFO(n << " lockers");
    const dg::TriangleMesh resized = resized_along(one, 0, n);
    CHECK(narrow_components(resized) == static_cast<std::size_t>(n));  // one handle per locker
    CHECK(resized.bounds().size().x() == Approx(0.6 * n).margin(1e-9));
  }
  // The grammar file keeps the split.
  dg::Model again;
  again.mesh = lockers(5);
  const dg::ShapeGrammar grammar = dg::test::model_grammar(std::move(again), false);
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-lockers-grammar");
  dg::write_grammar(folder / "lockers.grammar.json", grammar);
  const dg::ShapeGrammar read = dg::read_grammar(folder / "lockers.grammar.json");
  REQUIRE(read.grids.size() == 1);
  CHECK(read.grids[0].rule.directions[0].split_unit);
  CHECK(read.grids[0].rule.directions[0].count == 5);
}

TEST_CASE("a row of keys on a plate that ends half a pitch beyond the last ones counts every key", "[grammar][grid]") {
  // 12 x 4 keys at a pitch of 0.025 on a plate 0.3 long: the plate's end faces lie where the first and
  // last units end; compared without them, the end slabs are copies of the unit.
  dg::Model model;
  model.mesh = dg::test::make_box(Vec3(-0.15, -0.055, 0.0), Vec3(0.15, 0.055, 0.02));
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 4; ++j) {
      const double x = -0.1375 + 0.025 * i, y = -0.0375 + 0.025 * j;
      dg::test::append(model.mesh, dg::test::make_box(Vec3(x - 0.0095, y - 0.0095, 0.02), Vec3(x + 0.0095, y + 0.0095, 0.034)));
    }
  // The same keyboard turned by 0.7 rad about z, then 0.4 about x, and moved.
  const dg::Mat3 turn = (Eigen::AngleAxisd(0.4, Vec3::UnitX()) * Eigen::AngleAxisd(0.7, Vec3::UnitZ())).toRotationMatrix();
  dg::Model turned;
  turned.mesh = dg::transformed(model.mesh, dg::RigidTransform{turn, Vec3(3.0, -2.0, 1.0)});
  for (Vec3& p : turned.mesh.positions) p = (p * 1e6).array().round() / 1e6;  // as an OBJ with 6 decimals stores it
  const dg::PreparedModel prepared = dg::prepare_model(std::move(model));
  const std::vector<dg::GridRule> grids = grids_of(prepared);
  REQUIRE(!grids.empty());
  const dg::GridDirection* keys = direction_along(grids[0], Vec3(0.025, 0, 0));
  REQUIRE(keys != nullptr);
  CHECK(keys->count == 12);
  // Turned and stored with 6 decimals (as a user's OBJ may lie), the detected motion's direction
  // carries noise: the plate's end faces lean against the planes across it and still count as
  // its end caps, and the split unit's parts, which end at them, still match the unit's.
  const dg::PreparedModel turned_prepared = dg::prepare_model(std::move(turned));
  const std::vector<dg::GridRule> turned_grids = grids_of(turned_prepared);
  REQUIRE(!turned_grids.empty());
  const dg::GridDirection* along = nullptr;  // the detected translation is the turned pitch up to its noise
  for (const dg::GridDirection& d : turned_grids[0].directions)
    if (std::abs(std::abs(d.direction.dot(turn * Vec3::UnitX())) - 1.0) < 1e-4) along = &d;
  REQUIRE(along != nullptr);
  CHECK(along->count == 12);
}

namespace {

// A bookshelf of `books` per row: two sides 0.04 thick, a back, four boards and three rows of
// books 0.15 wide at a pitch of 0.2, the first and last 0.025 from the sides.
dg::TriangleMesh bookshelf(int books) {
  const double width = 0.2 * books;
  dg::TriangleMesh mesh;
  dg::test::append(mesh, dg::test::make_box(Vec3(-0.04, -0.15, 0.0), Vec3(0.0, 0.15, 1.8)));
  dg::test::append(mesh, dg::test::make_box(Vec3(width, -0.15, 0.0), Vec3(width + 0.04, 0.15, 1.8)));
  dg::test::append(mesh, dg::test::make_box(Vec3(-0.04, 0.15, 0.0), Vec3(width + 0.04, 0.17, 1.8)));
  for (int k = 0; k < 4; ++k) dg::test::append(mesh, dg::test::make_box(Vec3(0.0, -0.15, 0.58 * k), Vec3(width, 0.15, 0.58 * k + 0.04)));
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < books; ++i) {
      const double x = 0.025 + 0.2 * i, z = 0.04 + 0.58 * k;
      dg::test::append(mesh, dg::test::make_box(Vec3(x, -0.11, z), Vec3(x + 0.15, 0.11, z + 0.28)));
    }
  return mesh;
}

}  // namespace

TEST_CASE("a bookshelf counts every book, the first and last against its sides", "[grammar][grid]") {
  // The sides begin where the first book's and the last book's units end (planes may not lie
  // there: they hold the sides' faces), so those units are compared without the sides' faces.
  const OneGrid one = one_grid(bookshelf(10));
  const dg::GridDirection* row = direction_along(one.grid, Vec3(0.2, 0, 0));
  const dg::GridDirection* rows = direction_along(one.grid, Vec3(0, 0, 0.58));
  REQUIRE(row != nullptr);
  REQUIRE(rows != nullptr);
  CHECK(row->count == 10);
  CHECK(rows->count == 3);
  const std::size_t along = static_cast<std::size_t>(row - one.grid.directions.data());
  for (int n : {dg::lowest_count(one.grid, along), 5, 10, 13}) {
    INFO(n << " books a row");
    const dg::TriangleMesh resized = resized_along(one, along, n);
    CHECK(components_measuring(resized, Vec3(0.15, 0.22, 0.28)) == static_cast<std::size_t>(3 * n));  // books
    CHECK(resized.bounds().size().x() == Approx(0.2 * n + 0.08).margin(1e-9));
  }
  // Resized to its own counts, the bookshelf is the exemplar.
  CHECK(dg::test::hausdorff_distance(resized_along(one, along, 10), bookshelf(10)) < 1e-3 * one.prepared.surface.eps());
}

namespace {

// A colonnade of `columns` at a pitch of 2 (each a base, a shaft and a capital, separate boxes)
// on three steps under a beam; the beam ends 0.3 beyond the outer capitals and the steps further,
// so no slab around an end column is a copy of the others'.
dg::TriangleMesh colonnade(int columns) {
  const double length = 2.0 * columns;
  dg::TriangleMesh mesh;
  for (int k = 0; k < 3; ++k) {
    const double margin = 0.3 - 0.2 * k;
    dg::test::append(mesh, dg::test::make_box(Vec3(-margin, -0.5 + 0.2 * k, 0.2 * k), Vec3(length + margin, 2.5 - 0.2 * k, 0.2 * k + 0.2)));
  }
  for (int i = 0; i < columns; ++i) {
    const double x = 1.0 + 2.0 * i;
    dg::test::append(mesh, dg::test::make_box(Vec3(x - 0.4, 0.6, 0.6), Vec3(x + 0.4, 1.4, 0.7)));
    dg::test::append(mesh, dg::test::make_box(Vec3(x - 0.25, 0.75, 0.7), Vec3(x + 0.25, 1.25, 3.7)));
    dg::test::append(mesh, dg::test::make_box(Vec3(x - 0.4, 0.6, 3.7), Vec3(x + 0.4, 1.4, 3.8)));
  }
  dg::test::append(mesh, dg::test::make_box(Vec3(0.3, 0.3, 3.8), Vec3(length - 0.3, 1.7, 4.3)));
  return mesh;
}

}  // namespace

TEST_CASE("a colonnade counts its end columns, whose slabs hold the ends of its beam and steps", "[grammar][grid]") {
  // Planes fit 7 units; the eighth column stands in a slab with the beam's and steps' ends. Its
  // parts (base, shaft, capital) are copies of the unit's own parts, so it counts, kept once.
  const OneGrid one = one_grid(colonnade(8));
  REQUIRE(one.grid.directions.size() == 1);
  const dg::GridDirection& row = one.grid.directions[0];
  CHECK(std::abs(row.direction.x()) == Approx(1.0));
  CHECK(row.count == 8);
  for (int n : {dg::lowest_count(one.grid, 0), 4, 8, 11}) {
    INFO(n << " columns");
    const dg::TriangleMesh resized = resized_along(one, 0, n);
    CHECK(components_measuring(resized, Vec3(0.5, 0.5, 3.0)) == static_cast<std::size_t>(n));  // shafts
    CHECK(resized.bounds().size().x() == Approx(2.0 * n + 0.6).margin(1e-9));
  }
  CHECK(dg::test::hausdorff_distance(resized_along(one, 0, 8), colonnade(8)) < 1e-3 * one.prepared.surface.eps());
}

TEST_CASE("a chain of rings turned a quarter turn each gives a 1-grid of its links along the screw", "[grammar][grid]") {
  // Two links on is a translation too (a half turn of the screw and each ring's own half turn),
  // but its units would hold two links: the screw's, one link each, are the grid.
  const OneGrid one = one_grid(dg::test::make_chain(9));
  REQUIRE(one.grid.directions.size() == 1);
  const dg::GridDirection& links = one.grid.directions[0];
  const dg::ScrewParameters screw = dg::screw_parameters(links.motion);
  CHECK(screw.angle * 180.0 / std::numbers::pi == Approx(90.0).margin(1e-3));
  CHECK(std::abs(screw.slide) == Approx(1.5).margin(1e-6));
  CHECK(links.count == 9);
  for (int n : {dg::lowest_count(one.grid, 0), 4, 9, 13}) {
    INFO(n << " links");
    const dg::TriangleMesh resized = resized_along(one, 0, n);
    CHECK(component_boxes(resized).size() == static_cast<std::size_t>(n));  // one ring each
    CHECK(resized.bounds().size().x() == Approx(1.5 * (n - 1) + 2.3).margin(1e-9));
  }
  CHECK(dg::test::hausdorff_distance(resized_along(one, 0, 9), dg::test::make_chain(9)) < 1e-3 * one.prepared.surface.eps());
}

namespace {

// A wall of staggered bricks (0.2 x 0.065 x 0.1, 0.01 apart): `rows` courses of `bricks` along
// x, every second course shifted by half a brick, with a half brick at each of its ends.
dg::TriangleMesh brick_wall(int bricks, int rows) {
  constexpr double length = 0.2, height = 0.065, depth = 0.1, gap = 0.01, pitch = length + gap;
  dg::TriangleMesh mesh;
  auto brick = [&](double x0, double x1, double y) {
    dg::test::append(mesh, dg::test::make_box(Vec3(x0, y, 0.0), Vec3(x1, y + height, depth)));
  };
  for (int row = 0; row < rows; ++row) {
    const double y = row * (height + gap);
    if (row % 2 == 0) {
      for (int b = 0; b < bricks; ++b) brick(b * pitch, b * pitch + length, y);
      continue;
    }
    brick(0.0, 0.5 * pitch - gap, y);
    for (int b = 0; b + 1 < bricks; ++b) brick((b + 0.5) * pitch, (b + 0.5) * pitch + length, y);
    brick((bricks - 0.5) * pitch, bricks * pitch - gap, y);
  }
  return mesh;
}

}  // namespace

TEST_CASE("a staggered brick wall: a 2-grid along the brick pitch and two courses, not the screw of half a brick",
          "[grammar][grid]") {
  // A half turn about the wall's length with a slide of half a brick maps the courses onto one
  // another, so its screw has twice the units of the brick pitch; the pitch still makes the 2-grid
  // with the courses, which the screw could not join.
  dg::Model model;
  model.mesh = brick_wall(8, 6);
  const dg::PreparedModel prepared = dg::prepare_model(std::move(model));
  const dg::SymmetryResult symmetries = dg::detect_symmetries(prepared);
  const bool half_brick_screw = std::any_of(symmetries.symmetries.begin(), symmetries.symmetries.end(), [](const auto& s) {
    const dg::ScrewParameters screw = dg::screw_parameters(s.transform);
    return s.kind == "screw" && std::abs(std::abs(screw.slide) - 0.105) < 1e-3 && std::abs(screw.axis.x()) > 0.999;
  });
  REQUIRE(half_brick_screw);
  const std::vector<dg::GridRule> grids = dg::find_grids(prepared, symmetries);
  REQUIRE(grids.size() == 1);
  REQUIRE(grids[0].directions.size() == 2);
  const dg::GridDirection* along = direction_along(grids[0], Vec3(0.21, 0, 0));
  const dg::GridDirection* up = direction_along(grids[0], Vec3(0, 0.15, 0));
  REQUIRE(along != nullptr);
  REQUIRE(up != nullptr);
  CHECK(along->count == 8);  // the bricks of a full course
  CHECK(up->count == 3);
  const std::vector<dg::GridPiece> pieces = dg::cut_grid_pieces(prepared.model.mesh, grids[0], prepared.surface.eps());
  std::vector<int> counts(2);
  counts[along == &grids[0].directions[0] ? 0 : 1] = 10;
  counts[up == &grids[0].directions[0] ? 0 : 1] = 5;
  const dg::TriangleMesh resized = dg::resize_grid(grids[0], pieces, counts, prepared.surface.eps());
  CHECK(dg::test::hausdorff_distance(resized, brick_wall(10, 10)) < 1e-3 * prepared.surface.eps());
}

namespace {

// A footbridge of `spans` spans 5 long along x: a deck, a pier under each joint (half a pier at
// each end), a post every 1 and a handrail on the posts.
dg::TriangleMesh footbridge(int spans) {
  const double length = 5.0 * spans;
  dg::TriangleMesh mesh;
  auto box = [&](double x0, double y0, double z0, double x1, double y1, double z1) {
    dg::test::append(mesh, dg::test::make_box(Vec3(x0, y0, z0), Vec3(x1, y1, z1)));
  };
  box(0.0, 0.0, 2.0, length, 2.0, 2.3);
  for (int k = 0; k <= spans; ++k) box(std::max(0.0, 5.0 * k - 0.3), 0.6, 0.0, std::min(length, 5.0 * k + 0.3), 1.4, 2.0);
  for (int k = 0; k <= 5 * spans; ++k) {
    const double x = std::clamp(k - 0.04, 0.0, length - 0.08);
    box(x, 0.05, 2.3, x + 0.08, 0.13, 3.2);
  }
  box(0.0, 0.03, 3.2, length, 0.15, 3.3);
  return mesh;
}

}  // namespace

TEST_CASE("a footbridge: a 1-grid of its spans, not of the posts between two piers", "[grammar][grid]") {
  // The post pitch repeats 17 times, but planes at it fit only between two piers (4 units): its
  // fifth power, one span with its pier, spans the rest.
  const OneGrid one = one_grid(footbridge(4));
  REQUIRE(one.grid.directions.size() == 1);
  const dg::GridDirection* spans = direction_along(one.grid, Vec3(5, 0, 0));
  REQUIRE(spans != nullptr);
  CHECK(spans->count == 3);  // the inner piers, as a fence counts its inner posts
  for (int n : {1, 3, 5}) {
    INFO(n << " inner piers");
    CHECK(dg::test::hausdorff_distance(resized_along(one, 0, n), footbridge(n + 1)) < 1e-3 * one.prepared.surface.eps());
  }
}

namespace {

// A stack of crates 0.6 x 0.4 x 0.4 with a handle on the front, `across` along x (pitch 0.65),
// `deep` along y (0.45) and `high` along z (0.42): gaps between them along every axis.
dg::TriangleMesh crates(int across, int deep, int high) {
  dg::TriangleMesh mesh;
  for (int i = 0; i < across; ++i)
    for (int j = 0; j < deep; ++j)
      for (int k = 0; k < high; ++k) {
        const Vec3 corner(0.65 * i, 0.45 * j, 0.42 * k);
        dg::test::append(mesh, dg::test::make_box(corner, corner + Vec3(0.6, 0.4, 0.4)));
        dg::test::append(mesh, dg::test::make_box(corner + Vec3(0.25, -0.02, 0.3), corner + Vec3(0.35, 0.0, 0.35)));
      }
  return mesh;
}

// A table top 0.6 n + 0.4 long with n chairs along one side at a pitch of 0.6, z up: seat, four
// legs touching it and a back standing on it, none touching the top.
dg::TriangleMesh table_with_chairs(int n) {
  dg::TriangleMesh mesh = dg::test::make_box(Vec3(0, -0.45, 0.72), Vec3(0.6 * n + 0.4, 0.45, 0.76));
  for (int i = 0; i < n; ++i) {
    const double x = 0.5 + 0.6 * i;
    dg::test::append(mesh, dg::test::make_box(Vec3(x - 0.2, 0.55, 0.42), Vec3(x + 0.2, 0.95, 0.46)));
    for (const double dx : {-0.17, 0.17})
      for (const double dy : {-0.17, 0.17})
        dg::test::append(mesh, dg::test::make_box(Vec3(x + dx - 0.02, 0.75 + dy - 0.02, 0), Vec3(x + dx + 0.02, 0.75 + dy + 0.02, 0.42)));
    dg::test::append(mesh, dg::test::make_box(Vec3(x - 0.2, 0.92, 0.46), Vec3(x + 0.2, 0.96, 0.9)));
  }
  return mesh;
}

// The grid of make(n), a row of n units along `translation` built in code: one direction that
// counts n, whose resizes to n and n + 2 units are make(n) and make(n + 2). Returns the grid.
OneGrid check_row(dg::TriangleMesh (*make)(int), int n, const Vec3& translation) {
  OneGrid one = one_grid(make(n));
  REQUIRE(one.grid.directions.size() == 1);
  const dg::GridDirection& row = one.grid.directions[0];
  CHECK(row.translation.isApprox(translation, 1e-6));
  CHECK(row.count == n);
  const double eps = one.prepared.surface.eps();
  CHECK(dg::test::hausdorff_distance(resized_along(one, 0, n), make(n)) < 1e-3 * eps);
  CHECK(dg::test::hausdorff_distance(resized_along(one, 0, n + 2), make(n + 2)) < 1e-3 * eps);
  return one;
}

// A town house of `floors` storeys above a ground floor (z up, 1 x 1, storeys 0.4 high from
// z = 0.5): a plain body, a door and a cornice (0.42 to 0.5) at the ground floor, a small window
// box (0.3 x 0.2, 0.03 deep) on the front of each storey, and a roof ledge from 0.02 below the top
// storey's ceiling, so the top storey's slab holds the ledge's underside. A storey's window is
// 8.6 % of its surface.
dg::TriangleMesh town_house(int floors) {
  const double top = 0.5 + 0.4 * floors;
  dg::TriangleMesh mesh = dg::test::make_box(Vec3(0, 0, 0), Vec3(1, 1, top + 0.1));
  dg::test::append(mesh, dg::test::make_box(Vec3(0.1, 1, 0), Vec3(0.3, 1.03, 0.35)));
  dg::test::append(mesh, dg::test::make_box(Vec3(-0.03, -0.03, 0.42), Vec3(1.03, 1.03, 0.5)));
  for (int k = 0; k < floors; ++k)
    dg::test::append(mesh, dg::test::make_box(Vec3(0.35, 1, 0.6 + 0.4 * k), Vec3(0.65, 1.03, 0.8 + 0.4 * k)));
  dg::test::append(mesh, dg::test::make_box(Vec3(-0.05, -0.05, top - 0.02), Vec3(1.05, 1.05, top + 0.12)));
  return mesh;
}

// A straight stair of `steps` steps (run 0.3, rise 0.18, 1 wide along y, z up): one solid whose
// top is the steps' zigzag and whose underside runs parallel to the pitch line 0.35 below the
// inner corners, cut off by vertical faces at both ends, with a baluster on every tread.
dg::TriangleMesh straight_stair(int steps) {
  constexpr double run = 0.3, rise = 0.18, width = 1.0;
  std::vector<std::pair<double, double>> profile;  // (x, z), along the top, then the underside back
  for (int i = 0; i < steps; ++i) {
    if (i > 0) profile.emplace_back(i * run, i * rise);
    profile.emplace_back(i * run, (i + 1) * rise);
  }
  profile.emplace_back(steps * run, steps * rise);
  profile.emplace_back(steps * run, steps * rise - 0.35);
  profile.emplace_back(0.0, -0.35);
  dg::TriangleMesh mesh;
  const auto n = static_cast<std::uint32_t>(profile.size());
  for (const double y : {0.0, width})
    for (const auto& [x, z] : profile) mesh.positions.emplace_back(x, y, z);
  std::vector<std::uint32_t> back(n), front(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    back[i] = n + i;
    front[i] = n - 1 - i;  // the y = 0 side faces -y: its corners the other way round
  }
  for (const auto& side : {front, back})
    for (const dg::Triangle& t : dg::triangulate_polygon(mesh.positions, side)) mesh.triangles.push_back(t);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    mesh.triangles.push_back({i, j, n + j});
    mesh.triangles.push_back({i, n + j, n + i});
  }
  for (int i = 0; i < steps; ++i) {
    const double top = (i + 1) * rise;
    dg::test::append(mesh, dg::test::make_box(Vec3(i * run + 0.13, 0.9, top), Vec3(i * run + 0.17, 0.94, top + 0.9)));
  }
  return mesh;
}

}  // namespace

// Every plane crosses the stair's one body, and no phase of the planes makes the top step's slab
// a copy (the stair's end face lies in it), so the top step was left in the tail: 9 units for 10
// steps. Its tread is a copy of the unit's, so it counts as a unit kept in the tail.
TEST_CASE("a straight stair with a baluster on every tread: a 1-grid with one unit per step", "[grammar][grid]") {
  for (const int steps : {5, 10}) {
    CAPTURE(steps);
    check_row(straight_stair, steps, Vec3(0.3, 0, 0.18));
  }
  // Turned about a general axis: the tread, moved by the detected motion, still lands on the top one.
  dg::Model turned;
  turned.mesh = straight_stair(10);
  dg::test::turn_generally(turned.mesh);
  const std::vector<dg::GridRule> grids = grids_of(dg::prepare_model(std::move(turned)));
  REQUIRE(grids.size() == 1);
  REQUIRE(grids[0].directions.size() == 1);
  CHECK(grids[0].directions[0].count == 10);
}

// No plane may pass the top storey's ceiling (the roof ledge begins 0.02 below it), so the
// chain of planes between storeys ends a storey short and the top storey, kept in the tail,
// counts by its own part, the window: 8.6 % of its surface (a unit's own parts once had to make
// up 10 %, and the storeys counted one short, as the Kenney town house's did).
TEST_CASE("a town house whose roof ledge reaches into its top storey counts every storey", "[grammar][grid]") {
  for (const int floors : {3, 5}) {
    CAPTURE(floors);
    check_row(town_house, floors, Vec3(0, 0, 0.4));
  }
}

// The chairs hold every seed of the translation by the chair pitch; the top, apart from them,
// was never reached, so it counted as asymmetric, no plane could cross it, and the grid passed
// the planes by the chairs instead, the last one moved with the tail: count 3.
TEST_CASE("a table top beside four chairs it does not touch: a 1-grid of four whose planes cross the top",
          "[grammar][grid]") {
  const OneGrid one = check_row(table_with_chairs, 4, Vec3(0.6, 0, 0));
  CHECK(one.grid.directions[0].whole_in_head.empty());
  CHECK(one.grid.directions[0].whole_in_tail.empty());
}

TEST_CASE("a stack of 2 x 2 x 2 crates: a 3-grid of two units each way, though it spans less than two pitches",
          "[grammar][grid]") {
  // Each direction's second unit is a copy beyond the planes: the stack spans two pitches less
  // one gap.
  dg::Model model;
  model.mesh = crates(2, 2, 2);
  dg::PrepareOptions options;
  options.r = 0.05;  // the default (1.6 % of 1.25) spends a minute on 400k cells
  const dg::PreparedModel prepared = dg::prepare_model(std::move(model), options);
  const std::vector<dg::GridRule> grids = grids_of(prepared);
  REQUIRE(grids.size() == 1);
  const dg::GridRule& grid = grids[0];
  REQUIRE(grid.directions.size() == 3);
  const std::array<Vec3, 3> pitches{Vec3(0.65, 0, 0), Vec3(0, 0.45, 0), Vec3(0, 0, 0.42)};
  const std::array<int, 3> wanted{3, 4, 2};  // crates along x, y and z after the resize
  std::vector<int> counts(3, 0);
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const dg::GridDirection* direction = direction_along(grid, pitches[axis]);
    REQUIRE(direction != nullptr);
    CHECK(direction->count == 2);
    counts[static_cast<std::size_t>(direction - grid.directions.data())] = wanted[axis];
  }
  const std::vector<dg::GridPiece> pieces = dg::cut_grid_pieces(prepared.model.mesh, grid, prepared.surface.eps());
  const dg::TriangleMesh resized = dg::resize_grid(grid, pieces, counts, prepared.surface.eps());
  CHECK(dg::test::hausdorff_distance(resized, crates(3, 4, 2)) < 1e-3 * prepared.surface.eps());
}

TEST_CASE("a row of three crates counts three: the row spans less than three pitches, yet leaves room for a third",
          "[grammar][grid]") {
  // At r = 0.05 the first chain found has two units between planes and no copy beyond them; the
  // row, 1.9 long at a pitch of 0.65, has room for a third unit at another phase.
  dg::Model model;
  model.mesh = crates(3, 1, 1);
  dg::PrepareOptions options;
  options.r = 0.05;
  const dg::PreparedModel prepared = dg::prepare_model(std::move(model), options);
  const std::vector<dg::GridRule> grids = grids_of(prepared);
  REQUIRE(grids.size() == 1);
  const dg::GridDirection* row = direction_along(grids[0], Vec3(0.65, 0, 0));
  REQUIRE(row != nullptr);
  CHECK(row->count == 3);
  const std::vector<dg::GridPiece> pieces = dg::cut_grid_pieces(prepared.model.mesh, grids[0], prepared.surface.eps());
  std::vector<int> counts = dg::exemplar_counts(grids[0]);
  counts[static_cast<std::size_t>(row - grids[0].directions.data())] = 5;
  CHECK(dg::test::hausdorff_distance(dg::resize_grid(grids[0], pieces, counts, prepared.surface.eps()), crates(5, 1, 1)) <
        1e-3 * prepared.surface.eps());
}

TEST_CASE("corpus: FlightGear's terrace of 17 houses gives a 1-grid of 17", "[grammar][grid][corpus]") {
  const std::optional<std::filesystem::path> terrace =
      dg::test::corpus_file_if_present("meshes/arch-fg-terrace17/terrace17-1.obj");
  if (!terrace) return;
  const dg::PreparedModel prepared = dg::prepare_model(*terrace);
  // Ground truth from the mesh: two chimney stacks (separate parts of 10 triangles) per house.
  const std::size_t houses = components_of_size(prepared.model.mesh, 10) / 2;
  REQUIRE(houses == 17);
  const std::vector<dg::GridRule> grids = grids_of(prepared);
  REQUIRE(grids.size() == 1);
  REQUIRE(grids[0].directions.size() == 1);
  // The house at one end has its stacks beyond the last plane, the other's gable wall before the
  // first: together one house, split between the ends.
  CHECK(grids[0].directions[0].count == static_cast<int>(houses));
}

TEST_CASE("fence(9) with posts set up to 0.15 eps out of line: the whole grid needs a wider tolerance", "[grammar][grid]") {
  dg::Model model;
  model.mesh = dg::assets::make_asset("fence", {{"n", 9}}).mesh;
  // Every second inner post (x = k * 2 m, k odd) stands 0.15 eps of the default voxel (r = 1.6 %
  // of the longest side, eps = r / 4) out of line, as if placed by hand: its front and back
  // faces move across the fence; where it meets the rails nothing moves.
  const Vec3 size = model.mesh.bounds().max - model.mesh.bounds().min;
  const double eps = 0.016 * size.maxCoeff() / 4.0, shift = 0.15 * eps;
  for (Vec3& p : model.mesh.positions)
    for (int k = 1; k <= 9; k += 2)
      if (std::abs(p.x() - 2.0 * k) <= 0.05 + 1e-9 && std::abs(p.y()) > 0.049) p.y() += shift;
  const dg::PreparedModel prepared = dg::prepare_model(std::move(model));
  REQUIRE(prepared.surface.eps() == Approx(eps));
  auto units = [&](double tolerance) {
    dg::SymmetryOptions options;
    options.region.offset_tolerance_eps = tolerance;
    const std::vector<dg::GridRule> grids = dg::find_grids(prepared, dg::detect_symmetries(prepared, options));
    int most = 0;
    for (const dg::GridRule& g : grids)
      if (const dg::GridDirection* along = direction_along(g, Vec3(2.0, 0, 0)); along != nullptr) most = std::max(most, along->count);
    return most;
  };
  CHECK(units(dg::RegionOptions{}.offset_tolerance_eps) < 9);  // exact matching: the moved posts break the run
  CHECK(units(0.25) == 9);                                      // ground truth: 9 inner posts
}

TEST_CASE("facade(3 x 4): one 2-grid along the column and row pitches with the generator's counts", "[grammar][grid]") {
  const Analysis a = analyze_asset("facade", {{"columns", 3}, {"rows", 4}});
  REQUIRE(a.grids.size() == 1);
  REQUIRE(a.grids[0].directions.size() == 2);
  const dg::GridDirection* columns = direction_along(a.grids[0], Vec3(3.0, 0, 0));
  const dg::GridDirection* rows = direction_along(a.grids[0], Vec3(0, 0, 3.0));
  REQUIRE(columns != nullptr);
  REQUIRE(rows != nullptr);
  CHECK(columns->count == 3);
  CHECK(rows->count == 4);

  // Nine piece classes: corners once, borders along one direction, the interior in both.
  const std::vector<dg::GridPiece> pieces = dg::cut_grid_pieces(a.prepared.model.mesh, a.grids[0], a.prepared.surface.eps());
  CHECK(pieces.size() == 9);
  double area = 0.0;
  for (const auto& piece : pieces) area += piece.mesh.area();
  // The pieces hold one unit per repeated direction: corners + borders + one interior cell.
  CHECK(area < a.prepared.model.mesh.area());
}

TEST_CASE("shelf(n x m): a 2-grid along the column and row pitches that resizes into the generator's shelves", "[grammar][grid]") {
  // Columns repeat every cell width plus a divider (0.35 + 0.018), rows every cell height plus a
  // board (0.3 + 0.018). Two columns or two rows: the middle divider lies within r of the second
  // unit's asymmetric side, so only planes in the eroded area frame the two copies.
  for (const auto& [columns, rows] : std::vector<std::pair<int, int>>{{3, 4}, {5, 3}, {4, 2}, {2, 5}}) {
    CAPTURE(columns, rows);
    const Analysis a = analyze_asset("shelf", {{"columns", columns}, {"rows", rows}});
    REQUIRE(a.grids.size() == 1);
    const dg::GridRule& grid = a.grids[0];
    CHECK(grid.directions.size() == 2);
    const dg::GridDirection* along_columns = direction_along(grid, Vec3(0.368, 0, 0));
    const dg::GridDirection* along_rows = direction_along(grid, Vec3(0, 0, 0.318));
    REQUIRE(along_columns != nullptr);
    REQUIRE(along_rows != nullptr);
    // Ground truth: one unit per column and per row, the outer ones included (their boards are
    // thicker than the dividers, so only copies beyond the planes reach them).
    CHECK(along_columns->count == columns);
    CHECK(along_rows->count == rows);
    // The exemplar's counts rebuild it; one more unit in each direction is the generator's shelf
    // with one more column and one more row.
    const std::vector<dg::GridPiece> pieces = dg::cut_grid_pieces(a.prepared.model.mesh, grid, a.prepared.surface.eps());
    std::vector<int> counts;
    for (const dg::GridDirection& d : grid.directions) counts.push_back(d.count);
    const dg::TriangleMesh rebuilt = dg::resize_grid(grid, pieces, counts, a.prepared.surface.eps());
    CHECK(dg::test::hausdorff_distance(rebuilt, a.prepared.model.mesh) < 0.1 * a.prepared.surface.eps());
    for (int& count : counts) ++count;
    const dg::TriangleMesh resized = dg::resize_grid(grid, pieces, counts, a.prepared.surface.eps());
    const dg::TriangleMesh larger = dg::assets::make_asset("shelf", {{"columns", columns + 1}, {"rows", rows + 1}}).mesh;
    CHECK(resized.area() == Approx(larger.area()).epsilon(1e-3));
    CHECK(dg::test::hausdorff_distance(resized, larger) < 0.1 * a.prepared.surface.eps());
  }
}

TEST_CASE("facade(3 x 4) turned about a general axis: the same 2-grid along the turned pitches", "[grammar][grid]") {
  // Its motions no longer carry the voxel grid onto itself; the grid must not depend on that.
  const std::vector<dg::GridRule> grids = turned_grids("facade", {{"columns", 3}, {"rows", 4}});
  const Eigen::Matrix3d rotation = dg::test::general_rotation();
  REQUIRE(grids.size() == 1);
  REQUIRE(grids[0].directions.size() == 2);
  // The detected pitches are fitted to the mesh: within 1e-3 of the turned generator pitches.
  auto count_along = [&](const Vec3& t) {
    for (const auto& d : grids[0].directions)
      if ((d.translation - t).norm() < 1e-3 || (d.translation + t).norm() < 1e-3) return d.count;
    return -1;
  };
  CHECK(count_along(rotation * Vec3(3.0, 0, 0)) == 3);
  CHECK(count_along(rotation * Vec3(0, 0, 3.0)) == 4);
}

TEST_CASE("shelf(3 x 4) turned about a general axis: one unit per column and per row", "[grammar][grid]") {
  // Turned, the thin dividers' cells no longer map cleanly onto the voxels, so the planes through
  // them that reach the outer rows and columns are blocked; copies side by side, checked on the
  // mesh, still count them (the ground truth of the upright shelf).
  const std::vector<dg::GridRule> grids = turned_grids("shelf", {{"columns", 3}, {"rows", 4}});
  const Eigen::Matrix3d rotation = dg::test::general_rotation();
  REQUIRE(grids.size() == 1);
  REQUIRE(grids[0].directions.size() == 2);
  const dg::GridDirection* along_columns = direction_along(grids[0], rotation * Vec3(0.368, 0, 0));
  const dg::GridDirection* along_rows = direction_along(grids[0], rotation * Vec3(0, 0, 0.318));
  REQUIRE(along_columns != nullptr);
  REQUIRE(along_rows != nullptr);
  CHECK(along_columns->count == 3);
  CHECK(along_rows->count == 4);
}

TEST_CASE("messy facade: the clean facade's grid, 3 columns and 4 rows", "[grammar][grid]") {
  // Back-to-back duplicate faces no longer break symmetry (planes compare up to sign); the
  // non-manifold fin leaves a few asymmetric cells in a column, which the slab test absorbs
  // (GridOptions::max_slab_asymmetry). The fin stands within r above the place of the lowest
  // row plane; that plane may still go there because all the asymmetry near it lies above it.
  const Analysis a = analyze_asset("messy_facade", {{"columns", 3}, {"rows", 4}});
  const Analysis clean = analyze_asset("facade", {{"columns", 3}, {"rows", 4}});
  REQUIRE(a.grids.size() == 1);
  REQUIRE(clean.grids.size() == 1);
  for (const Analysis* analysis : {&a, &clean}) {
    const dg::GridDirection* columns = direction_along(analysis->grids[0], Vec3(3.0, 0, 0));
    const dg::GridDirection* rows = direction_along(analysis->grids[0], Vec3(0, 0, 3.0));
    REQUIRE(columns != nullptr);
    REQUIRE(rows != nullptr);
    CHECK(columns->count == 3);
    CHECK(rows->count == 4);
  }
  dg::GridOptions strict;
  strict.max_slab_asymmetry = 0.0;
  // Without that tolerance the fin's column breaks the run of columns (at most one unit is left).
  const std::vector<dg::GridRule> strict_grids = dg::find_grids(a.prepared, a.symmetries, strict);
  const dg::GridDirection* strict_columns =
      strict_grids.empty() ? nullptr : direction_along(strict_grids[0], Vec3(3.0, 0, 0));
  CHECK((strict_columns == nullptr || strict_columns->count < 3));
}

TEST_CASE("spiral stairs: a 1-grid along the screw motion with one unit per step", "[grammar][grid]") {
  // 30 and 20 steps climb more than one turn: a full turn (12 or 8 steps) is also a translation
  // along the axis, with 2 units; the screw's units are the steps. Above 3 steps of 120 degrees
  // the column rises 1 m (5 pitches) more: its faceted slabs, turned onto each other by the
  // screw, are an extrusion, no unit.
  for (const auto& [steps, per_turn] : std::vector<std::pair<int, int>>{{12, 12}, {30, 12}, {20, 8}, {3, 3}}) {
    CAPTURE(steps, per_turn);
    const Analysis a = analyze_asset("spiral_stairs", {{"steps", steps}, {"steps_per_turn", per_turn}});
    REQUIRE(a.grids.size() == 1);
    REQUIRE(a.grids[0].directions.size() == 1);
    const dg::GridDirection& d = a.grids[0].directions[0];
    const dg::ScrewParameters screw = dg::screw_parameters(d.motion);
    CHECK(screw.angle * 180 / 3.14159265358979 == Approx(360.0 / per_turn).margin(0.1));  // ground truth per step
    CHECK(std::abs(screw.slide) == Approx(0.18).margin(1e-3));                            // the rise
    CHECK(std::abs(screw.axis.z()) == Approx(1).margin(1e-3));
    CHECK(d.direction.isApprox(Vec3(0, 0, 1), 1e-6));  // cut planes across the axis
    CHECK(d.count == steps);                           // count = steps
  }
}

TEST_CASE("gear: no translational grid for a full rotation group", "[grammar][grid]") {
  const Analysis a = analyze_asset("gear", {{"teeth", 12}});
  CHECK(a.grids.empty());
}

TEST_CASE("corpus: the Sweet Home 3D railing gives a 1-grid along the baluster pitch", "[grammar][grid][corpus]") {
  const std::optional<std::filesystem::path> railing = dg::test::corpus_file_if_present("meshes/arch-sh3d-railing/railing.obj");
  if (!railing) return;
  const dg::PreparedModel prepared = dg::prepare_model(*railing);
  const dg::SymmetryResult symmetries = dg::detect_symmetries(prepared);
  const std::vector<dg::GridRule> grids = dg::find_grids(prepared, symmetries);
  REQUIRE(grids.size() == 1);
  const dg::GridDirection* balusters = direction_along(grids[0], Vec3(0.118, 0, 0));
  REQUIRE(balusters != nullptr);
  // 8 balusters: 7 units between cut planes, and one split between the ends: the rails' stubs
  // before the first plane and the eighth baluster after the last make one unit together
  // (docs/grammar-file.md).
  CHECK(balusters->count == 8);
  CHECK(balusters->head_units == 1);
}

TEST_CASE("corpus: Kenney building-small-c: a slide along its flat walls joins no grid", "[grammar][grid][corpus]") {
  const std::optional<std::filesystem::path> building =
      dg::test::corpus_file_if_present("meshes/arch-kenney-building-small-c/building-small-c.glb");
  if (!building) return;
  const dg::PreparedModel prepared = dg::prepare_model(*building);
  // Verifying every candidate finds t = (0.06, 0, 0): it slides the walls between the window
  // columns along themselves (several of its powers match, none pins a unit in place).
  dg::SymmetryOptions options;
  options.max_verified = 400;
  const dg::SymmetryResult symmetries = dg::detect_symmetries(prepared, options);
  auto is_wall_slide = [&](const dg::DetectedSymmetry& s) {
    return s.kind == "translation" && (s.transform.translation - Vec3(0.06, 0, 0)).norm() < 1e-3 &&
           s.pinned_fraction < options.min_r_symmetric_fraction;
  };
  const bool slide_found = std::any_of(symmetries.symmetries.begin(), symmetries.symmetries.end(), is_wall_slide);
  REQUIRE(slide_found);
  const std::vector<dg::GridRule> grids = dg::find_grids(prepared, symmetries);
  // Ground truth: three storeys of windows above the shop floor, 0.4 apart (their frames touch,
  // from y = 0.55 to 1.75); no column repeats across the whole building (the door and the shop
  // window differ), so the grid has that direction only. The top storey's slab also holds the
  // roof's underside and counts by its window faces (7.9 % of the storey's surface).
  REQUIRE(grids.size() == 1);
  REQUIRE(grids[0].directions.size() == 1);
  const dg::GridDirection* floors = direction_along(grids[0], Vec3(0, 0.4, 0));
  REQUIRE(floors != nullptr);
  CHECK(floors->count == 3);
  // Every vertex height of the three storeys' frames recurs 0.4 higher within them.
  std::vector<double> heights;
  for (const Vec3& p : prepared.model.mesh.positions)
    if (p.y() > 0.55 - 1e-6 && p.y() < 1.75 + 1e-6) heights.push_back(p.y());
  std::sort(heights.begin(), heights.end());
  heights.erase(std::unique(heights.begin(), heights.end(), [](double a, double b) { return b - a < 1e-5; }), heights.end());
  auto has_height = [&](double y) {
    return std::any_of(heights.begin(), heights.end(), [&](double h) { return std::abs(h - y) < 1e-5; });
  };
  for (const double y : {0.55, 0.725, 0.775, 0.9})
    for (int storey = 0; storey < 3; ++storey) CHECK(has_height(y + 0.4 * storey));
}

TEST_CASE("corpus: the Kenney metal gate gives a grid along the stake pitch with one unit per gap", "[grammar][grid][corpus]") {
  const std::optional<std::filesystem::path> gate = dg::test::corpus_file_if_present("meshes/arch-kenney-castle-metalgate/metal_gate.obj");
  if (!gate) return;
  const dg::PreparedModel prepared = dg::prepare_model(*gate);
  // Ground truth from the mesh itself: the stakes' flat tops are the faces at the highest y, one
  // quad per stake, so the distinct z of the top vertices come in pairs.
  const dg::TriangleMesh& mesh = prepared.model.mesh;
  const double top = mesh.bounds().max.y();
  std::vector<double> top_z;
  for (const Vec3& p : mesh.positions)
    if (p.y() > top - 1e-6) top_z.push_back(p.z());
  std::sort(top_z.begin(), top_z.end());
  top_z.erase(std::unique(top_z.begin(), top_z.end(), [](double a, double b) { return b - a < 1e-4; }), top_z.end());
  REQUIRE(top_z.size() % 2 == 0);
  const int stakes = static_cast<int>(top_z.size() / 2);
  REQUIRE(stakes >= 3);
  const double pitch = top_z[2] - top_z[0];

  // The source's beams are fans whose edges skip stake vertices (T-junctions); prepare_model
  // splits them, so no open edge runs along a beam and every gap between stakes repeats.
  CHECK(prepared.cleaning.t_junctions_split > 0);
  const dg::SymmetryResult symmetries = dg::detect_symmetries(prepared);
  const std::vector<dg::GridRule> grids = dg::find_grids(prepared, symmetries);
  REQUIRE(!grids.empty());
  const dg::GridDirection* along_stakes = nullptr;
  for (const dg::GridDirection& d : grids[0].directions)
    if (std::abs(std::abs(d.direction.z()) - 1) < 1e-4 && std::abs(d.pitch - pitch) < 1e-3) along_stakes = &d;
  REQUIRE(along_stakes != nullptr);
  // One unit per stake: the end stakes, which the beams end at, are kept once in the head and
  // tail, counted because their flat faces are copies of the unit's.
  CHECK(along_stakes->count == stakes);
}

TEST_CASE("corpus: the Sweet Home 3D spiral staircase gives a 1-grid of its steps along the screw", "[grammar][grid][corpus]") {
  const std::optional<std::filesystem::path> stairs = dg::test::corpus_file_if_present("meshes/arch-sh3d-spiral-staircase/spiralStaircase.obj");
  if (!stairs) return;
  // Its handrail is swept in 8-degree segments while the steps turn by 22.5 degrees, so only
  // tessellation-tolerant matching lets cut planes cross the rail.
  const dg::PreparedModel prepared = dg::prepare_model(*stairs);
  const dg::TriangleMesh& mesh = prepared.model.mesh;
  // Ground truth from the mesh: the treads (material "amber") are slabs whose horizontal top
  // faces lie at distinct heights, one per step.
  std::uint32_t amber = 0;
  while (amber < prepared.model.materials.size() && prepared.model.materials[amber].name != "amber") ++amber;
  REQUIRE(amber < prepared.model.materials.size());
  std::vector<double> tread_tops;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3 n = mesh.area_vector(t).normalized();
    if (mesh.materials[t] == amber && n.y() > 0.99) tread_tops.push_back(mesh.positions[mesh.triangles[t][0]].y());
  }
  std::sort(tread_tops.begin(), tread_tops.end());
  tread_tops.erase(std::unique(tread_tops.begin(), tread_tops.end(), [](double a, double b) { return b - a < 1e-3; }),
                   tread_tops.end());
  REQUIRE(tread_tops.size() >= 10);
  const double rise = tread_tops[1] - tread_tops[0];

  const dg::SymmetryResult symmetries = dg::detect_symmetries(prepared);
  const std::vector<dg::GridRule> grids = dg::find_grids(prepared, symmetries);
  REQUIRE(grids.size() == 1);
  REQUIRE(grids[0].directions.size() == 1);
  const dg::GridDirection& d = grids[0].directions[0];
  const dg::ScrewParameters screw = dg::screw_parameters(d.motion);
  CHECK(std::abs(screw.axis.y()) == Approx(1).margin(1e-3));  // the pole is vertical
  CHECK(std::abs(screw.slide) == Approx(rise).margin(2e-3));
  CHECK(screw.angle * 180 / 3.14159265358979 == Approx(22.5).margin(0.1));  // 16 steps per turn
  // One unit per tread (13 steps, balusters and fixings): the top step's slab also holds the
  // rail's end, so it is kept once, counted because its parts are copies of the unit's.
  CHECK(d.count == static_cast<int>(tread_tops.size()));
}

TEST_CASE("corpus: the Hochhaus Asemwald gives a 2-grid of floors and bays when its window tints count as one",
          "[grammar][grid][corpus][materials]") {
  const std::optional<std::filesystem::path> hochhaus = dg::test::corpus_file_if_present("meshes/arch-fg-hochhaus-asemwald/hochhaus_asemwald.obj");
  if (!hochhaus) return;
  // Its facades are flat: floors and bays exist only in materials, and each window's glass has
  // one of four tints or two blinds, chosen at random.
  dg::PrepareOptions options;
  options.same_materials = {"glas*,jalousie*"};
  const dg::PreparedModel prepared = dg::prepare_model(*hochhaus, options);
  const dg::TriangleMesh& mesh = prepared.model.mesh;
  const std::vector<dg::Material>& materials = prepared.model.materials;
  // Ground truth from the mesh: the most common gap between the window bands' lower edges
  // (lowest corner of each glass or blind triangle) is the floor pitch, the most common gap
  // between the pillars' left edges (grau70) the bay pitch.
  std::vector<double> band_bottoms, pillar_lefts, pillar_bottoms;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::string& name = materials[mesh.materials[t]].name;
    const auto [a, b, c] = mesh.corners(t);
    if (name.starts_with("glas") || name.starts_with("jalousie")) band_bottoms.push_back(std::min({a.y(), b.y(), c.y()}));
    if (name == "grau70") {
      pillar_lefts.push_back(std::min({a.x(), b.x(), c.x()}));
      pillar_bottoms.push_back(std::min({a.y(), b.y(), c.y()}));
    }
  }
  // The most common gap between distinct values (rounded to 1e-3) and the longest run of values
  // that gap apart.
  auto pitch_and_run = [](std::vector<double> values) {
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end(), [](double a, double b) { return b - a < 1e-3; }), values.end());
    std::map<long, int> gaps;
    for (std::size_t i = 1; i < values.size(); ++i) ++gaps[std::lround(1e3 * (values[i] - values[i - 1]))];
    REQUIRE(!gaps.empty());
    const long mode =
        std::max_element(gaps.begin(), gaps.end(), [](const auto& a, const auto& b) { return a.second < b.second; })->first;
    int run = 1, longest = 1;
    for (std::size_t i = 1; i < values.size(); ++i) {
      run = std::lround(1e3 * (values[i] - values[i - 1])) == mode ? run + 1 : 1;
      longest = std::max(longest, run);
    }
    return std::pair{1e-3 * static_cast<double>(mode), longest};
  };
  const auto [floor_pitch, bands] = pitch_and_run(band_bottoms);
  const double bay_pitch = pitch_and_run(pillar_lefts).first;
  REQUIRE(bands >= 20);

  const dg::SymmetryResult symmetries = dg::detect_symmetries(prepared);
  const std::vector<dg::GridRule> grids = dg::find_grids(prepared, symmetries);
  REQUIRE(!grids.empty());
  REQUIRE(grids[0].directions.size() == 2);
  const dg::GridDirection* floors = nullptr;
  const dg::GridDirection* bays = nullptr;
  for (const dg::GridDirection& d : grids[0].directions) {
    if (std::abs(std::abs(d.direction.y()) - 1) < 1e-4 && std::abs(d.pitch - floor_pitch) < 1e-2) floors = &d;
    if (std::abs(std::abs(d.direction.x()) - 1) < 1e-4 && std::abs(d.pitch - bay_pitch) < 1e-2) bays = &d;
  }
  REQUIRE(floors != nullptr);
  REQUIRE(bays != nullptr);
  // One unit per window band: the floors with the facade's grey pillars, and the top floor below
  // the roof, which has none and is kept once in the tail (its windows' flat faces, the unit's
  // own, are copies of the unit's).
  std::set<long> pillar_floors;
  for (double y : pillar_bottoms) pillar_floors.insert(std::lround(std::floor(y / floor_pitch + 1e-6)));
  REQUIRE(pillar_floors.size() == 20);
  CHECK(bands == 21);
  CHECK(floors->count == bands);
  CHECK(floors->tail_units >= 1);
  // Structures on the roof stand across all bays but one, so planes through the whole building
  // fit one bay (the report says so); resizing adds bays there.
  CHECK(bays->count == 1);
}

// Grid1 counts the 9 window columns, but keeps all but those between two pilasters once (the
// pilasters break the copies every third column); the grid of bays repeats, and resizing it
// adds whole bays (before, only grid1 was built, and resizing it added windows between two
// pilasters).
TEST_CASE("a facade with a pilaster every third window column also gives a grid of bays", "[grammar][grid]") {
  dg::Model model;
  model.mesh = dg::test::pilaster_facade(9, 2);
  const dg::PreparedModel prepared = dg::prepare_model(std::move(model));
  const std::vector<dg::GridRule> grids = grids_of(prepared);
  REQUIRE(grids.size() == 2);
  const dg::GridDirection* columns = direction_along(grids[0], Vec3(1.5, 0, 0));
  REQUIRE(columns != nullptr);
  CHECK(columns->count == 9);
  CHECK(dg::min_units(*columns) > 4);
  const dg::GridRule& bays = grids[1];
  REQUIRE(bays.directions.size() == grids[0].directions.size());
  const dg::GridDirection* bay = direction_along(bays, Vec3(4.5, 0, 0));
  REQUIRE(bay != nullptr);
  CHECK(bay->count == 3);
  const dg::GridDirection* storeys = direction_along(bays, Vec3(0, 3, 0));
  REQUIRE(storeys != nullptr);
  CHECK(storeys->count == 2);
  const std::vector<dg::GridPiece> pieces = dg::cut_grid_pieces(prepared.model.mesh, bays, prepared.surface.eps());
  const auto bay_index = static_cast<std::size_t>(bay - bays.directions.data());
  const auto storey_index = static_cast<std::size_t>(storeys - bays.directions.data());
  for (const auto& [bay_count, storey_count] : {std::pair{4, 2}, std::pair{2, 3}, std::pair{3, 2}}) {
    std::vector<int> counts(2);
    counts[bay_index] = bay_count;
    counts[storey_index] = storey_count;
    const dg::TriangleMesh resized = dg::resize_grid(bays, pieces, counts, prepared.surface.eps());
    CHECK(dg::test::hausdorff_distance(resized, dg::test::pilaster_facade(3 * bay_count, storey_count)) < 1e-3 * prepared.surface.eps());
  }
}

TEST_CASE("corpus: the Blendswap pallet also gives a grid of its deck boards grouped by its bottom boards",
          "[grammar][grid][corpus]") {
  const std::optional<std::filesystem::path> pallet = dg::test::corpus_file_if_present("meshes/furn-blendswap-pallet/pallet.obj");
  if (!pallet) return;
  const dg::PreparedModel prepared = dg::prepare_model(*pallet);
  // Ground truth from the mesh: deck boards are the parts reaching its top, bottom boards those
  // reaching its bottom, both across x and one pitch deep along z.
  auto boards = [](const dg::TriangleMesh& mesh, bool deck) {
    const dg::BoundingBox all = mesh.bounds();
    std::vector<double> z;
    for (const dg::BoundingBox& b : component_boxes(mesh))
      if (b.size().x() > 0.9 * all.size().x() && (deck ? b.max.y() > all.max.y() - 1e-3 : b.min.y() < all.min.y() + 1e-3))
        z.push_back(b.min.z());
    std::sort(z.begin(), z.end());
    return z;
  };
  const std::vector<double> deck = boards(prepared.model.mesh, true), bottom = boards(prepared.model.mesh, false);
  REQUIRE(deck.size() == 7);
  REQUIRE(bottom.size() == 3);
  const double pitch = deck[1] - deck[0];
  CHECK(bottom[1] - bottom[0] == Approx(3 * pitch).margin(1e-3));  // a bottom board under every third deck board

  const std::vector<dg::GridRule> grids = dg::find_grids(prepared, dg::detect_symmetries(prepared));
  REQUIRE(grids.size() == 2);
  // The direction of `grid` along z with pitch `along` (the file's pitches carry float rounding).
  auto along_z = [](const dg::GridRule& grid, double along) -> const dg::GridDirection* {
    for (const dg::GridDirection& d : grid.directions)
      if (std::abs(d.direction.z()) > 0.999 && std::abs(d.pitch - along) < 1e-3) return &d;
    return nullptr;
  };
  const dg::GridDirection* boards_along = along_z(grids[0], pitch);
  REQUIRE(boards_along != nullptr);
  CHECK(boards_along->count == 7);
  const dg::GridRule& grouped = grids[1];
  const dg::GridDirection* bays = along_z(grouped, 3 * pitch);
  REQUIRE(bays != nullptr);
  CHECK(bays->count == 2);
  // One bay more: three more deck boards and one more bottom board.
  std::vector<int> counts = dg::exemplar_counts(grouped);
  counts[static_cast<std::size_t>(bays - grouped.directions.data())] = 3;
  const std::vector<dg::GridPiece> pieces = dg::cut_grid_pieces(prepared.model.mesh, grouped, prepared.surface.eps());
  const dg::TriangleMesh longer = dg::resize_grid(grouped, pieces, counts, prepared.surface.eps());
  CHECK(boards(longer, true).size() == 10);
  CHECK(boards(longer, false).size() == 4);
}
