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

namespace {

// A band around a square stem of side 0.1 centred at (x, y): points on its four sides within
// `height` of z = 0, normals outwards.
dg::OrientedPoints stem_band(double x, double y, double height) {
  dg::OrientedPoints band;
  for (int side = 0; side < 4; ++side) {
    const Vec3 normal = side == 0 ? Vec3(1, 0, 0) : side == 1 ? Vec3(-1, 0, 0) : side == 2 ? Vec3(0, 1, 0) : Vec3(0, -1, 0);
    const Vec3 along = Vec3(0, 0, 1).cross(normal);
    for (int i = -2; i <= 2; ++i)
      for (int k = 0; k <= 2; ++k) {
        band.points.push_back(Vec3(x, y, 0.0) + 0.05 * normal + 0.02 * i * along + Vec3(0, 0, height * k / 2.0));
        band.normals.push_back(normal);
      }
  }
  return band;
}

}  // namespace

TEST_CASE("slippage: loops around stems far apart slide only along the stems together", "[symmetry]") {
  // Eight thin bands around stems spread over 3 x 3 model units: analysed as one set, their
  // thin height (0.05) makes tilting about horizontal axes look slippable too.
  std::vector<dg::OrientedPoints> loops;
  dg::OrientedPoints together;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 2; ++j) {
      loops.push_back(stem_band(0.8 * i, 3.2 * j, 0.05));
      together.points.insert(together.points.end(), loops.back().points.begin(), loops.back().points.end());
      together.normals.insert(together.normals.end(), loops.back().normals.begin(), loops.back().normals.end());
    }
  CHECK(dg::slippage(together.points, together.normals).dimension() == 3);
  CHECK(dg::joint_slippage_dimension(loops) == 1);
  CHECK(dg::joint_slippage_dimension({loops.front()}) == dg::slippage(loops.front().points, loops.front().normals).dimension());

  // Patches of one plane slide in it together (2 translations and the turn about its normal).
  std::vector<dg::OrientedPoints> patches(3);
  for (int p = 0; p < 3; ++p)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        patches[p].points.emplace_back(2.0 * p + 0.1 * i, 0.1 * j, 1.0);
        patches[p].normals.emplace_back(0, 0, 1);
      }
  CHECK(dg::joint_slippage_dimension(patches) == 3);
  // A patch on another plane locks the motions that lift off it.
  dg::OrientedPoints wall;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      wall.points.emplace_back(0.0, 0.1 * i, 2.0 + 0.1 * j);
      wall.normals.emplace_back(1, 0, 0);
    }
  patches.push_back(wall);
  CHECK(dg::joint_slippage_dimension(patches) == 1);  // only the slide along both planes (y)
  CHECK(dg::joint_slippage_dimension({}) == 6);
  // A part locked in place (no slippable motion) locks every other part with it.
  dg::OrientedPoints box;
  sample_mesh(dg::test::make_box(Vec3(5, 0, 0), Vec3(6, 1, 1)), box.points, box.normals);
  CHECK(dg::joint_slippage_dimension({loops.front(), box}) == 0);
}
