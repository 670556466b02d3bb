// asymmetric_spans on a flat slab: the symmetric cells within r of the asymmetric end see that
// end's positions, the others see none.

#include "grammar/asymmetric_spans.h"

#include "geometry/feature_edges.h"
#include "support/shapes.h"

#include <catch2/catch.hpp>

TEST_CASE("asymmetric spans: only cells within r of the asymmetry see it, at its positions", "[grammar][grid]") {
  const double eps = 0.1, r = 0.5, border = 6.0;
  const dg::TriangleMesh slab = dg::test::make_box(dg::Vec3(0.03, 0.03, 0.03), dg::Vec3(10.03, 0.13, 1.03));
  dg::VoxelSurfaceOptions options;
  options.r = r;
  options.eps = eps;
  const dg::VoxelSurface surface = dg::build_voxel_surface(slab, dg::find_feature_edges(slab), options);
  // Cells whose centre lies beyond x = 6 count as asymmetric.
  std::vector<char> symmetric(surface.cell_count());
  for (std::uint32_t c = 0; c < surface.cell_count(); ++c) symmetric[c] = surface.centre(c).x() < border ? 1 : 0;
  const std::vector<dg::PositionSpan> spans = dg::asymmetric_spans(surface, symmetric, dg::Vec3::UnitX(), r);

  std::size_t near = 0, far = 0;
  for (std::uint32_t c = 0; c < surface.cell_count(); ++c) {
    const double x = surface.centre(c).x();
    if (!symmetric[c]) {
      CHECK(spans[c].empty());
    } else if (x < border - r - eps) {  // farther than r along the surface from every asymmetric cell
      CHECK(spans[c].empty());
      ++far;
    } else if (x > border - r + eps) {  // an asymmetric neighbour lies within r
      REQUIRE(!spans[c].empty());
      CHECK(spans[c].lo > border);
      CHECK(spans[c].hi < border + r + eps);
      ++near;
    }
  }
  CHECK(near > 0);
  CHECK(far > 0);
}
