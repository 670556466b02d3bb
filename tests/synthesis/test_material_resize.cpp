// A resized grid gives every triangle the material of the exemplar surface it copies: checked
// against the ground truth of the material fence and facade (tests/support/material_models.h).

#include "synthesis/grid_resize.h"

#include "grammar/grid_cut.h"
#include "support/asset_grammar.h"
#include "support/material_models.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>

using dg::Vec3;

namespace {

// Surface area per material of a mesh with three materials.
std::array<double, 3> area_by_material(const dg::TriangleMesh& mesh) {
  std::array<double, 3> area{};
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) area[mesh.materials[t]] += 0.5 * mesh.area_vector(t).norm();
  return area;
}

// Resizes the grammar's only grid to `counts` and checks every triangle's material against
// `rule` at its centroid and normal, and each material's area against the generator's model `expected`.
template <class Rule>
void check_resize(const dg::ShapeGrammar& grammar, const std::vector<int>& counts, Rule rule, const dg::Model& expected) {
  REQUIRE(grammar.grids.size() == 1);
  const dg::TriangleMesh resized =
      dg::resize_grid(grammar.grids[0].rule, grammar.grids[0].pieces, counts, grammar.eps);
  REQUIRE(resized.has_materials());
  for (std::size_t t = 0; t < resized.triangles.size(); ++t) {
    const auto [a, b, c] = resized.corners(t);
    INFO("triangle " << t << " at " << ((a + b + c) / 3.0).transpose());
    CHECK(resized.materials[t] == rule((a + b + c) / 3.0, resized.area_vector(t).normalized()));
  }
  const std::array<double, 3> want = area_by_material(expected.mesh), got = area_by_material(resized);
  for (std::size_t m = 0; m < 3; ++m) CHECK(got[m] == Approx(want[m]).epsilon(1e-9));
}

}  // namespace

TEST_CASE("materials: resizing the material fence keeps each surface's material", "[synthesis][grid][materials]") {
  const dg::ShapeGrammar grammar = dg::test::model_grammar(dg::test::material_fence(4), false);
  for (const int count : {4, 7}) {
    INFO("count " << count);
    check_resize(grammar, {count}, [](const Vec3& p, const Vec3& n) { return dg::test::fence_material_at(p, n); },
                 dg::test::material_fence(count));
  }
  // Pieces without materials give a result without them.
  dg::GridWithPieces plain = grammar.grids[0];
  for (dg::GridPiece& piece : plain.pieces) piece.mesh.materials.clear();
  CHECK_FALSE(dg::resize_grid(plain.rule, plain.pieces, {5}, grammar.eps).has_materials());
}

TEST_CASE("materials: a facade resized to 5 x 7 has glass in every window and oak in every door", "[synthesis][grid][materials]") {
  const dg::ShapeGrammar grammar = dg::test::model_grammar(dg::test::material_facade(3, 4), false);
  REQUIRE(grammar.grids.size() == 1);
  std::vector<int> counts;  // 5 columns along x, 7 rows along z
  for (const dg::GridDirection& d : grammar.grids[0].rule.directions) counts.push_back(std::abs(d.direction.x()) > 0.5 ? 5 : 7);
  REQUIRE(counts.size() == 2);
  check_resize(grammar, counts, dg::test::facade_material_at, dg::test::material_facade(5, 7));
  // Every window and door of the larger facade is there: 5 x 7 windows and 5 doors, each back
  // 1.2 x 1.5 and 1.4 x 2.6 m.
  const dg::TriangleMesh resized =
      dg::resize_grid(grammar.grids[0].rule, grammar.grids[0].pieces, counts, grammar.eps);
  CHECK(area_by_material(resized)[dg::test::kGlass] == Approx(5 * 7 * 1.2 * 1.5).epsilon(1e-9));
  CHECK(area_by_material(resized)[dg::test::kOak] == Approx(5 * 1.4 * 2.6).epsilon(1e-9));
}

TEST_CASE("materials: windows painted on a flat wall come back whole in a resized wall", "[synthesis][grid][materials]") {
  // The wall is one plane: only the materials keep window and wall apart when flat faces are
  // joined and re-triangulated per cell, and only --match-materials finds the grid.
  dg::PrepareOptions options;
  options.match_materials = true;
  const dg::ShapeGrammar grammar = dg::test::model_grammar(dg::test::painted_wall(6, 4), false, options);
  REQUIRE(grammar.grids.size() == 1);
  REQUIRE(grammar.grids[0].rule.directions.size() == 2);
  std::vector<int> counts;  // two more cells each way (n cells are n units)
  for (const dg::GridDirection& d : grammar.grids[0].rule.directions) counts.push_back(d.count + 2);
  const dg::TriangleMesh resized =
      dg::resize_grid(grammar.grids[0].rule, grammar.grids[0].pieces, counts, grammar.eps);
  REQUIRE(resized.has_materials());
  double glass = 0.0;
  for (std::size_t t = 0; t < resized.triangles.size(); ++t) {
    const auto [a, b, c] = resized.corners(t);
    INFO("triangle " << t << " at " << ((a + b + c) / 3.0).transpose());
    REQUIRE(resized.materials[t] == dg::test::painted_wall_material_at((a + b + c) / 3.0));
    if (resized.materials[t] != 1) continue;
    glass += 0.5 * resized.area_vector(t).norm();
    for (const Vec3& p : {a, b, c}) {  // inside its window, border included
      const double x = p.x() - 3.0 * std::floor(p.x() / 3.0 + 1e-9), y = p.y() - 2.0 * std::floor(p.y() / 2.0 + 1e-9);
      CHECK((x > 0.75 - 1e-9 && x < 2.25 + 1e-9 && y > 0.5 - 1e-9 && y < 1.5 + 1e-9));
    }
  }
  CHECK(glass == Approx(counts[0] * counts[1] * 1.5).epsilon(1e-9));
  CHECK(resized.area() == Approx(counts[0] * counts[1] * 6.0).epsilon(1e-9));
}
