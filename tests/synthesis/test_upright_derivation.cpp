// Upright derivation (ShapeDerivationOptions::up): some alternatives of the facade's
// context-free grammar turn window pieces by 90 degrees about the facade normal. Derived freely,
// some window recess stands landscape; upright, every one stays portrait as the generator built
// it. Alternatives that keep every piece upright remain, so automatic variants still use the
// context-free rules in both modes.

#include "synthesis/shape_derivation.h"
#include "synthesis/variants.h"

#include "assets/generator/asset.h"
#include "geometry/submesh.h"
#include "geometry/topology.h"
#include "support/asset_grammar.h"

#include <catch2/catch.hpp>

#include <cmath>

namespace {

// Width (x) and height (z) of every window recess of a facade: the connected faces of its back,
// which faces -y at the window depth behind the front (y = 0).
std::vector<std::pair<double, double>> window_sizes(const dg::TriangleMesh& mesh, double depth) {
  std::vector<std::size_t> backs;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const dg::Vec3 n = mesh.area_vector(t).normalized();
    bool on_plane = true;
    for (std::uint32_t v : mesh.triangles[t]) on_plane = on_plane && std::abs(mesh.positions[v].y() - depth) < 1e-6;
    if (on_plane && n.y() < -0.99) backs.push_back(t);
  }
  const dg::TriangleMesh back = dg::submesh(mesh, backs);
  std::size_t count = 0;
  const std::vector<std::uint32_t> component = dg::triangle_components(back, &count);
  std::vector<dg::BoundingBox> boxes(count);
  for (std::size_t t = 0; t < back.triangles.size(); ++t)
    for (std::uint32_t v : back.triangles[t]) boxes[component[t]].add(back.positions[v]);
  std::vector<std::pair<double, double>> sizes;
  for (const dg::BoundingBox& box : boxes) sizes.push_back({box.size().x(), box.size().z()});
  return sizes;
}

}  // namespace

TEST_CASE("upright derivation keeps the facade's windows portrait, free derivation turns some", "[synthesis][variants]") {
  const dg::assets::Asset asset = dg::assets::make_asset("facade", {{"columns", 3}, {"rows", 4}});
  const double width = asset.ground_truth["dimensions"]["window"][0], height = asset.ground_truth["dimensions"]["window"][1],
               depth = asset.ground_truth["dimensions"]["window"][2];
  REQUIRE(height > width);
  const dg::ShapeGrammar grammar = dg::test::asset_grammar("facade", {{"columns", 3}, {"rows", 4}}, true);
  REQUIRE(!grammar.context_free.empty());
  REQUIRE(window_sizes(grammar.exemplar, depth).size() == 12);

  auto landscape_windows = [&](const dg::TriangleMesh& mesh) {
    std::size_t landscape = 0;
    for (const auto& [x, z] : window_sizes(mesh, depth)) {
      CHECK(((std::abs(x - width) < 1e-6 && std::abs(z - height) < 1e-6) ||
             (std::abs(x - height) < 1e-6 && std::abs(z - width) < 1e-6)));
      landscape += x > z ? 1 : 0;
    }
    return landscape;
  };
  dg::ShapeDerivationOptions free, upright;
  upright.up = dg::Vec3::UnitZ();
  // Both have a choice: upright, the window types still swap among upright productions.
  CHECK(dg::derivation_has_choice(grammar.context_free, free));
  CHECK(dg::derivation_has_choice(grammar.context_free, upright));
  std::size_t turned = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    free.seed = upright.seed = seed;
    turned += landscape_windows(dg::derive_shape(grammar.context_free, grammar.eps, free).mesh);
    CHECK(landscape_windows(dg::derive_shape(grammar.context_free, grammar.eps, upright).mesh) == 0);
  }
  CHECK(turned > 0);

  dg::VariantOptions automatic;
  automatic.derivation = upright;
  CHECK(dg::plan_variant(grammar, 1, 0, automatic).context_free);
  automatic.derivation = free;
  CHECK(dg::plan_variant(grammar, 1, 0, automatic).context_free);
}
