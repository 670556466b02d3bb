// The material hint: repeats drawn in materials chosen at random (window tints) are found by
// the materials the model's translations swap, and grouping those gives the grid that geometry
// alone and materials matched one by one do not.

#include "grammar/material_hint.h"

#include "support/corpus.h"
#include "support/material_models.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

namespace {

// The painted wall with each window's glass in one of `tints` materials ("tint0", ...), chosen
// per cell by a fixed hash: glass no longer repeats with the cells, the window shapes do.
dg::Model tinted_wall(int columns, int rows, int tints) {
  dg::Model model = dg::test::painted_wall(columns, rows);
  model.materials = {{"wall", dg::Vec3(0.9, 0.9, 0.85)}};
  for (int k = 0; k < tints; ++k) model.materials.push_back({"tint" + std::to_string(k), dg::Vec3(0.3, 0.4, 0.5 + 0.1 * k)});
  for (std::size_t t = 0; t < model.mesh.triangles.size(); ++t) {
    if (model.mesh.materials[t] != 1) continue;
    const auto [a, b, c] = model.mesh.corners(t);
    const dg::Vec3 centre = (a + b + c) / 3.0;
    const auto column = static_cast<unsigned>(std::floor(centre.x() / dg::test::kPaintedPitchX));
    const auto row = static_cast<unsigned>(std::floor(centre.y() / dg::test::kPaintedPitchY));
    model.mesh.materials[t] = 1 + (column * 7 + row * 13 + column * row * 5) % static_cast<unsigned>(tints);
  }
  return model;
}

std::vector<std::vector<int>> sorted(std::vector<std::vector<int>> counts) {
  for (std::vector<int>& c : counts) std::sort(c.begin(), c.end());
  return counts;
}

}  // namespace

TEST_CASE("interchangeable materials: swapped ones are grouped, those that land on themselves are not", "[grammar][materials]") {
  // Rows: where each material lands (shares of its mapped area), after the Hochhaus Asemwald:
  // three glass tints swap at random with blinds, concrete and plaster mostly land on themselves.
  const std::vector<std::vector<double>> swaps = {
      {57, 15, 7, 0, 0, 6},   // glass1
      {55, 17, 7, 0, 0, 8},   // glass2
      {58, 18, 5, 0, 0, 7},   // glass3
      {4, 1, 0, 87, 6, 0},    // concrete
      {0, 0, 0, 10, 90, 0},   // plaster
      {58, 13, 8, 0, 0, 5}};  // blind
  const std::vector<std::vector<std::uint32_t>> groups = dg::interchangeable_materials(swaps);
  REQUIRE(groups.size() == 1);
  CHECK(groups[0] == std::vector<std::uint32_t>{0, 1, 2, 5});
  // Nothing swapped: no group.
  CHECK(dg::interchangeable_materials({{10, 0}, {0, 10}}).empty());
}

TEST_CASE("material hint: windows in three random tints give their grid once the tints are grouped", "[grammar][materials]") {
  const int columns = 6, rows = 4;
  const dg::PreparedModel prepared = dg::prepare_model(tinted_wall(columns, rows, 3));
  const dg::SymmetryResult symmetries = dg::detect_symmetries(prepared);
  REQUIRE(dg::find_grids(prepared, symmetries).empty());  // a flat wall: no repeat in geometry
  // Materials matched one by one: the tints break the repeat of the cells. The hash repeats its
  // tints every three columns, so the six columns are at most two copies of three.
  dg::PrepareOptions matched;
  matched.match_materials = true;
  const dg::PreparedModel painted = dg::prepare_model(tinted_wall(columns, rows, 3), matched);
  const std::vector<dg::GridRule> painted_grids = dg::find_grids(painted, dg::detect_symmetries(painted));
  REQUIRE(painted_grids.size() == 1);
  REQUIRE(painted_grids[0].directions.size() == 1);
  const dg::GridDirection& three_columns = painted_grids[0].directions[0];
  CAPTURE(three_columns.translation.transpose());
  CHECK((three_columns.translation.cwiseAbs() - dg::Vec3(3 * dg::test::kPaintedPitchX, 0, 0)).norm() < 1e-6);
  CHECK(three_columns.count == 2);

  const std::optional<dg::MaterialHint> hint = dg::material_hint(prepared, {}, {}, 0);
  REQUIRE(hint);
  REQUIRE(hint->groups.size() == 1);
  CHECK(hint->groups[0] == std::vector<std::string>{"tint0", "tint1", "tint2"});
  // The grouped wall's grid: one unit per cell, the end cells (within r of the wall's edges, no
  // plane crosses them) counted as copies because their tints belong to the group.
  CHECK(sorted(hint->grid_counts) == std::vector<std::vector<int>>{{rows, columns}});
  // No hint (no search) when analysis already found a grid or materials were matched.
  CHECK(dg::material_hint_applies(prepared, {}, 0));
  CHECK_FALSE(dg::material_hint_applies(prepared, {}, 1));
  CHECK_FALSE(dg::material_hint_applies(prepared, matched, 0));
  CHECK_FALSE(dg::material_hint(prepared, {}, {}, 1));
  CHECK_FALSE(dg::material_hint(prepared, matched, {}, 0));
}

TEST_CASE("material hint: windows in one material need --match-materials alone", "[grammar][materials]") {
  const dg::PreparedModel prepared = dg::prepare_model(dg::test::painted_wall(5, 3));
  const std::optional<dg::MaterialHint> hint = dg::material_hint(prepared, {}, {}, 0);
  REQUIRE(hint);
  CHECK(hint->groups.empty());
  CHECK(sorted(hint->grid_counts) == std::vector<std::vector<int>>{{3, 5}});  // one unit per cell
}

TEST_CASE("material hint: stripes of materials that never repeat give none", "[grammar][materials]") {
  const dg::PreparedModel prepared = dg::prepare_model(dg::test::striped_wall({0, 1, 2, 1, 0, 2, 2}, {"red", "green", "blue"}));
  CHECK_FALSE(dg::material_hint(prepared, {}, {}, 0));
}

TEST_CASE("corpus: the Hochhaus Asemwald's glass tints and blinds are grouped into its 2-grid", "[grammar][materials][corpus]") {
  const auto path = dg::test::corpus_file_if_present("meshes/arch-fg-hochhaus-asemwald/hochhaus_asemwald.obj");
  if (!path) return;
  const dg::PreparedModel prepared = dg::prepare_model(*path);
  const std::optional<dg::MaterialHint> hint = dg::material_hint(prepared, {}, {}, 0);
  REQUIRE(hint);
  REQUIRE(hint->groups.size() == 1);
  CHECK(hint->groups[0] == std::vector<std::string>{"glas1", "glas2", "glas3", "glas4", "jalousie1", "jalousie2"});
  // README: --same-material 'glas*,jalousie*' gives 21 floors (one per window band; the top
  // floor, without the facade's grey pillars, kept once, see test_grid_rules.cpp) and one bay.
  CHECK(sorted(hint->grid_counts) == std::vector<std::vector<int>>{{1, 21}});
}
