// same_surface and same_points: one surface however it is triangulated or sampled, and not
// when a part is missing or moved.

#include "geometry/same_surface.h"

#include "assets/generator/asset.h"
#include "geometry/submesh.h"
#include "geometry/surface_sampling.h"

#include <catch2/catch.hpp>

#include <cmath>

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

TEST_CASE("same_surface: one surface triangulated two ways is the same, with a dent it is not", "[geometry]") {
  // A 40 x 30 rectangle in z = 0, as 2 triangles and as a 4 x 3 grid of quads split along the
  // other diagonal; with tolerance 0.01 its sampling needs about 48 million cells of tolerance / 2,
  // so the cells grow (about a million) and the comparison stays quick.
  auto grid = [](int nx, int ny, bool flip, double dent) {
    dg::TriangleMesh mesh;
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) mesh.positions.emplace_back(40.0 * i / nx, 30.0 * j / ny, i == 1 && j == 1 ? dent : 0.0);
    auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (nx + 1) + i); };
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        if (flip) {
          mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
          mesh.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
        } else {
          mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
          mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
      }
    return mesh;
  };
  const double tolerance = 0.01;
  const dg::TriangleMesh two = grid(1, 1, false, 0.0), quads = grid(4, 3, true, 0.0);
  CHECK(dg::same_surface(two, quads, tolerance));
  CHECK(dg::same_surface(quads, two, tolerance));
  CHECK(dg::same_surface(quads, dg::transformed(quads, shift(0.2 * tolerance)), tolerance));  // twins
  // An inner vertex lifted by 2: a dent of 20 x 20 that the two triangles do not have.
  CHECK_FALSE(dg::same_surface(two, grid(4, 3, true, 2.0), tolerance));
  CHECK_FALSE(dg::same_surface(grid(4, 3, true, 2.0), quads, tolerance));
}

TEST_CASE("same_points: two samplings of one surface are the same, a cloud with a hole is not", "[geometry]") {
  const dg::TriangleMesh mesh = facade();
  const double tolerance = 0.05;
  const dg::PointCloud a = dg::sample_surface(mesh, 200000, 1), b = dg::sample_surface(mesh, 200000, 2);
  CHECK(dg::same_points(a, b, tolerance));
  CHECK_FALSE(dg::same_points(a, dg::transformed(b, shift(5.0 * tolerance)), tolerance));
  // With a hole of 1 x 1 model units in the middle: the same bounding box, but cells of one are
  // uncovered by the other.
  const dg::BoundingBox box = a.bounds();
  const dg::Vec3 middle = 0.5 * (box.min + box.max);
  dg::PointCloud holed;
  for (const dg::Vec3& p : a.positions)
    if (std::abs(p.x() - middle.x()) > 0.5 || std::abs(p.z() - middle.z()) > 0.5) holed.positions.push_back(p);
  REQUIRE(holed.positions.size() < a.positions.size());
  REQUIRE((holed.bounds().min - box.min).norm() < tolerance);
  REQUIRE((holed.bounds().max - box.max).norm() < tolerance);
  CHECK_FALSE(dg::same_points(a, holed, tolerance));
  CHECK_FALSE(dg::same_points(holed, a, tolerance));
  CHECK(dg::same_points(dg::PointCloud{}, dg::PointCloud{}, tolerance));
  CHECK_FALSE(dg::same_points(a, dg::PointCloud{}, tolerance));
}
