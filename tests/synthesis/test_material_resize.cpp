// A resized grid gives every triangle the material of the exemplar surface it copies: checked
// against the material fence's ground truth (tests/support/material_fence).

#include "synthesis/grid_resize.h"

#include "support/asset_grammar.h"
#include "support/material_fence.h"

#include <catch2/catch.hpp>

#include <array>

using dg::Vec3;

namespace {

// Surface area per material of a mesh with the material fence's three materials.
std::array<double, 3> area_by_material(const dg::TriangleMesh& mesh) {
  std::array<double, 3> area{};
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) area[mesh.materials[t]] += 0.5 * mesh.area_vector(t).norm();
  return area;
}

}  // namespace

TEST_CASE("materials: resizing the material fence keeps each surface's material", "[synthesis][grid][materials]") {
  const dg::ShapeGrammar grammar = dg::test::model_grammar(dg::test::material_fence(4), false);
  REQUIRE(grammar.grids.size() == 1);
  REQUIRE(grammar.grids[0].rule.directions.size() == 1);
  for (const int count : {4, 7}) {
    INFO("count " << count);
    const dg::TriangleMesh resized =
        dg::resize_grid(grammar.grids[0].rule, grammar.grids[0].pieces, {count}, dg::kSeamWeldFraction * grammar.eps);
    REQUIRE(resized.has_materials());
    for (std::size_t t = 0; t < resized.triangles.size(); ++t) {
      const auto [a, b, c] = resized.corners(t);
      INFO("triangle " << t << " at " << ((a + b + c) / 3.0).transpose());
      CHECK(resized.materials[t] == dg::test::fence_material_at((a + b + c) / 3.0));
    }
    // Each material covers as much surface as on the generator's fence of that length.
    const std::array<double, 3> expected = area_by_material(dg::test::material_fence(count).mesh);
    const std::array<double, 3> got = area_by_material(resized);
    for (std::size_t m = 0; m < 3; ++m) CHECK(got[m] == Approx(expected[m]).epsilon(1e-9));
  }
  // Pieces without materials give a result without them.
  dg::GridWithPieces plain = grammar.grids[0];
  for (dg::GridPiece& piece : plain.pieces) piece.mesh.materials.clear();
  CHECK_FALSE(dg::resize_grid(plain.rule, plain.pieces, {5}, dg::kSeamWeldFraction * grammar.eps).has_materials());
}
