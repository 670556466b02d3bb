#include "geometry/voxel_surface.h"

#include "geometry/errors.h"

#include "support/shapes.h"

#include <catch2/catch.hpp>
#include <tbb/global_control.h>

#include <algorithm>

using dg::Vec3;

namespace {

dg::VoxelSurface voxelize(const dg::TriangleMesh& mesh, double eps) {
  dg::VoxelSurfaceOptions options;
  options.r = 4.0 * eps;
  options.eps = eps;
  return dg::build_voxel_surface(mesh, dg::find_feature_edges(mesh), options);
}

}  // namespace

TEST_CASE("cube aligned with the grid touches the analytic number of closed voxels", "[geometry]") {
  // Cube [0, 1]^3 at eps 0.25 (n = 4): closed voxels meeting the surface are those meeting
  // the solid, (n + 2)^3, minus those strictly inside it, (n - 2)^3.
  const dg::VoxelSurface surface = voxelize(dg::test::make_box(Vec3(0, 0, 0), Vec3(1, 1, 1)), 0.25);
  CHECK(surface.cell_count() == 6 * 6 * 6 - 2 * 2 * 2);
  CHECK(surface.find({-1, -1, -1}) >= 0);  // touched only at the cube's corner
  CHECK(surface.find({1, 1, 1}) < 0);      // strictly inside
  CHECK(surface.find({4, 2, 2}) >= 0);     // touched by the face x = 1 from outside
}

TEST_CASE("cube off the grid touches the analytic number of voxels", "[geometry]") {
  // Cube [0.1, 1.1]^3 at eps 0.25: 5 voxels per axis meet it, 3 per axis lie strictly inside.
  const dg::VoxelSurface surface = voxelize(dg::test::make_box(Vec3(0.1, 0.1, 0.1), Vec3(1.1, 1.1, 1.1)), 0.25);
  CHECK(surface.cell_count() == 5 * 5 * 5 - 3 * 3 * 3);
  std::size_t components = 0;
  surface.components(&components);
  CHECK(components == 1);
}

TEST_CASE("a triangle touching a voxel only at a corner or an edge occupies it", "[geometry]") {
  dg::TriangleMesh corner;
  corner.positions = {Vec3(0.25, 0.25, 0.25), Vec3(0.45, 0.3, 0.35), Vec3(0.3, 0.45, 0.4)};
  corner.triangles = {{0, 1, 2}};
  const dg::VoxelSurface at_corner = voxelize(corner, 0.25);
  CHECK(at_corner.find({0, 0, 0}) >= 0);
  CHECK(at_corner.find({1, 1, 1}) >= 0);
  CHECK(at_corner.cell_count() == 8);  // the eight voxels around the shared corner point

  dg::TriangleMesh edge;  // one edge lies on the voxel edge x = 0.25, y = 0.25
  edge.positions = {Vec3(0.25, 0.25, 0.05), Vec3(0.25, 0.25, 0.2), Vec3(0.4, 0.4, 0.1)};
  edge.triangles = {{0, 1, 2}};
  const dg::VoxelSurface at_edge = voxelize(edge, 0.25);
  CHECK(at_edge.find({0, 0, 0}) >= 0);
  CHECK(at_edge.find({0, 1, 0}) >= 0);
  CHECK(at_edge.find({1, 0, 0}) >= 0);
  CHECK(at_edge.find({1, 1, 0}) >= 0);
  CHECK(at_edge.cell_count() == 4);
}

TEST_CASE("cells keep the exact planes and feature lines", "[geometry]") {
  const dg::VoxelSurface surface = voxelize(dg::test::make_box(Vec3(0.1, 0.1, 0.1), Vec3(1.1, 1.1, 1.1)), 0.25);
  // A voxel on the middle of the face z = 1.1: one plane (two coplanar triangles merged), no lines.
  const auto face = surface.find({2, 2, 4});
  REQUIRE(face >= 0);
  const auto planes = surface.planes(static_cast<std::uint32_t>(face));
  REQUIRE(planes.size() == 1);
  CHECK(planes[0].normal.isApprox(Vec3(0, 0, 1)));
  CHECK(planes[0].offset == Approx(1.1));
  CHECK(surface.lines(static_cast<std::uint32_t>(face)).empty());
  // The voxel at the corner (1.1, 1.1, 1.1): three planes and three feature lines.
  const auto corner = surface.find({4, 4, 4});
  REQUIRE(corner >= 0);
  CHECK(surface.planes(static_cast<std::uint32_t>(corner)).size() == 3);
  CHECK(surface.lines(static_cast<std::uint32_t>(corner)).size() == 3);
}

TEST_CASE("intrinsic distance follows a folded strip, not the straight line", "[geometry]") {
  // A U-shaped strip: lower plate z = 0, upper plate z = 1, joined by the wall x = 4.
  dg::TriangleMesh strip;
  strip.positions = {Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(4, 1, 0), Vec3(0, 1, 0),
                     Vec3(4, 0, 1), Vec3(4, 1, 1), Vec3(0, 0, 1), Vec3(0, 1, 1)};
  strip.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}, {4, 6, 7}, {4, 7, 5}};
  const double eps = 0.25;
  const dg::VoxelSurface surface = voxelize(strip, eps);
  const auto lower = surface.find(surface.voxel_of(Vec3(0.1, 0.6, 0.0)));
  const auto upper = surface.find(surface.voxel_of(Vec3(0.1, 0.6, 1.0)));
  REQUIRE(lower >= 0);
  REQUIRE(upper >= 0);
  const std::uint32_t source = static_cast<std::uint32_t>(lower);
  const std::vector<double> distance = surface.intrinsic_distance(std::span<const std::uint32_t>(&source, 1));
  const double euclidean = (surface.centre(source) - surface.centre(static_cast<std::uint32_t>(upper))).norm();
  const double along_strip = 4.0 + 1.0 + 4.0;
  CHECK(euclidean == Approx(1.0));
  CHECK(distance[static_cast<std::size_t>(upper)] > along_strip - 4 * eps);
  CHECK(distance[static_cast<std::size_t>(upper)] < along_strip + 4 * eps);
  // Along a straight row of voxels the distance is exact.
  const auto along = surface.find(surface.voxel_of(Vec3(2.1, 0.6, 0.0)));
  REQUIRE(along >= 0);
  CHECK(distance[static_cast<std::size_t>(along)] == Approx(2.0));
  // A cut-off distance leaves far cells unreached.
  const std::vector<double> near = surface.intrinsic_distance(std::span<const std::uint32_t>(&source, 1), 1.0);
  CHECK(std::isinf(near[static_cast<std::size_t>(upper)]));
}

TEST_CASE("voxel surface is independent of the thread count", "[geometry]") {
  dg::TriangleMesh mesh = dg::test::make_sphere(Vec3(0.03, 0.01, 0.02), 1.0, 40, 80);
  dg::test::append(mesh, dg::test::make_box(Vec3(1.5, 0, 0), Vec3(2.5, 0.7, 0.3)));
  auto build = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
    return voxelize(mesh, 0.05);
  };
  const dg::VoxelSurface one = build(1), two = build(2);
  REQUIRE(one.cell_count() == two.cell_count());
  std::size_t differences = 0;
  for (std::uint32_t c = 0; c < one.cell_count(); ++c) {
    if (one.coord(c) != two.coord(c)) ++differences;
    const auto tri1 = one.triangles(c), tri2 = two.triangles(c);
    if (!std::equal(tri1.begin(), tri1.end(), tri2.begin(), tri2.end())) ++differences;
    const auto p1 = one.planes(c), p2 = two.planes(c);
    if (p1.size() != p2.size()) ++differences;
    for (std::size_t k = 0; k < std::min(p1.size(), p2.size()); ++k)
      if (p1[k].normal != p2[k].normal || p1[k].offset != p2[k].offset) ++differences;
    const auto n1 = one.neighbours(c), n2 = two.neighbours(c);
    if (!std::equal(n1.begin(), n1.end(), n2.begin(), n2.end())) ++differences;
  }
  CHECK(differences == 0);
  std::size_t components = 0;
  one.components(&components);
  CHECK(components == 2);
}

TEST_CASE("point cloud voxels hold their points", "[geometry]") {
  dg::PointCloud cloud;
  cloud.positions = {Vec3(0.1, 0.1, 0.1), Vec3(0.2, 0.1, 0.1), Vec3(0.3, 0.1, 0.1), Vec3(2.0, 2.0, 2.0)};
  dg::VoxelSurfaceOptions options;
  options.r = 1.0;
  options.eps = 0.25;
  const dg::VoxelSurface surface = dg::build_voxel_surface(cloud, options);
  CHECK(surface.cell_count() == 3);
  const auto first = surface.find({0, 0, 0});
  REQUIRE(first >= 0);
  CHECK(surface.points(static_cast<std::uint32_t>(first)).size() == 2);
  std::size_t components = 0;
  surface.components(&components);
  CHECK(components == 2);
}

TEST_CASE("empty input is an input error", "[geometry]") {
  CHECK_THROWS_AS(dg::build_voxel_surface(dg::TriangleMesh{}, {}), dg::InputError);
  CHECK_THROWS_AS(dg::build_voxel_surface(dg::PointCloud{}), dg::InputError);
}

TEST_CASE("cell areas add up to the surface area", "[geometry]") {
  // Off the grid no face lies on a voxel plane, so the clipped pieces partition the surface.
  const dg::TriangleMesh cube = dg::test::make_box(Vec3(0.1, 0.1, 0.1), Vec3(1.1, 1.1, 1.1));
  const dg::VoxelSurface surface = voxelize(cube, 0.25);
  CHECK(surface.total_area() == Approx(6.0));
  const auto face = surface.find({2, 2, 4});
  REQUIRE(face >= 0);
  CHECK(surface.area(static_cast<std::uint32_t>(face)) == Approx(0.0625));
}
