#include "symmetry/slippage.h"

#include "support/shapes.h"

#include <catch2/catch.hpp>

#include <cmath>

using dg::Vec3;

namespace {

void sample_mesh(const dg::TriangleMesh& mesh, std::vector<Vec3>& points, std::vector<Vec3>& normals) {
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    const Vec3 n = mesh.area_vector(t).normalized();
    for (double u : {0.2, 0.6})
      for (double v : {0.2, 0.3}) {
        points.push_back(a + u * (b - a) + v * (c - a));
        normals.push_back(n);
      }
  }
}

}  // namespace

TEST_CASE("slippage: plane 3, sphere 3, cylinder 2, box 0 slippable motions", "[symmetry]") {
  std::vector<Vec3> points, normals;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) {
      points.emplace_back(i, j, 0.0);
      normals.emplace_back(0, 0, 1);
    }
  const dg::SlippageResult plane = dg::slippage(points, normals);
  CHECK(plane.dimension() == 3);
  for (const auto& m : plane.motions) CHECK(std::abs(m.translation.z()) < 1e-9);  // never lifts off the plane

  points.clear();
  normals.clear();
  sample_mesh(dg::test::make_sphere(Vec3(1, 2, 3), 2.0, 30, 60), points, normals);
  // Flat facets of a tessellated sphere are not exactly radial: loosen the threshold a little.
  CHECK(dg::slippage(points, normals, 1e-2).dimension() == 3);

  points.clear();
  normals.clear();
  for (int k = 0; k < 20; ++k)
    for (int s = 0; s < 36; ++s) {
      const double phi = 2.0 * M_PI * s / 36;
      points.emplace_back(std::cos(phi), std::sin(phi), 0.1 * k);
      normals.emplace_back(std::cos(phi), std::sin(phi), 0.0);
    }
  const dg::SlippageResult cylinder = dg::slippage(points, normals);
  REQUIRE(cylinder.dimension() == 2);

  points.clear();
  normals.clear();
  sample_mesh(dg::test::make_box(Vec3(0, 0, 0), Vec3(1, 2, 3)), points, normals);
  CHECK(dg::slippage(points, normals).dimension() == 0);
}
