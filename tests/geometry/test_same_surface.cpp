// same_surface and same_points: one surface however it is triangulated or sampled, and not
// when a part is missing or moved.

#include "geometry/same_surface.h"

#include "assets/generator/asset.h"
#include "geometry/submesh.h"
#include "geometry/surface_sampling.h"

#include <catch2/catch.hpp>

namespace {

dg::TriangleMesh facade() { return dg::assets::make_asset("facade", {{"columns", 2}, {"rows", 3}}).mesh; }

dg::RigidTransform shift(double x) { return {dg::Mat3::Identity(), dg::Vec3(x, 0.0, 0.0)}; }

}  // namespace

TEST_CASE("same_surface: a mesh moved within the tolerance is the same, moved farther it is not", "[geometry]") {
  const dg::TriangleMesh mesh = facade();
  const double tolerance = 0.05;
  CHECK(dg::same_surface(mesh, dg::transformed(mesh, shift(0.2 * tolerance)), tolerance));
  CHECK_FALSE(dg::same_surface(mesh, dg::transformed(mesh, shift(5.0 * tolerance)), tolerance));
}

TEST_CASE("same_points: two samplings of one surface are the same, a cloud missing a window is not", "[geometry]") {
  const dg::TriangleMesh mesh = facade();
  const double tolerance = 0.05;
  const dg::PointCloud a = dg::sample_surface(mesh, 200000, 1), b = dg::sample_surface(mesh, 200000, 2);
  CHECK(dg::same_points(a, b, tolerance));
  CHECK_FALSE(dg::same_points(a, dg::transformed(b, shift(5.0 * tolerance)), tolerance));
  // Without the points in front of the wall (the window frames and sills stand out of it).
  const double front = a.bounds().max.y();
  dg::PointCloud flat;
  for (const dg::Vec3& p : a.positions)
    if (p.y() < front - 2.0 * tolerance) flat.positions.push_back(p);
  REQUIRE(flat.positions.size() < a.positions.size());
  CHECK_FALSE(dg::same_points(a, flat, tolerance));
  CHECK(dg::same_points(dg::PointCloud{}, dg::PointCloud{}, tolerance));
  CHECK_FALSE(dg::same_points(a, dg::PointCloud{}, tolerance));
}
