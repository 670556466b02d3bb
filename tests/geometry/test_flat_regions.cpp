// Flat regions: coplanar flat faces taken together, also where they meet only at T-junctions,
// and whether two regions are one however each is triangulated.

#include "geometry/flat_regions.h"

#include "geometry/same_surface.h"

#include <catch2/catch.hpp>

#include <map>

using dg::Vec3;

namespace {

// Appends an nx x ny grid of quads over [x0, x0 + w] x [y0, y0 + h] at height z, two triangles
// each (facing +z, or -z with `down`), reusing vertices at the same spot; quads (i, j) listed
// in `skip` are left out (holes).
void add_grid(dg::TriangleMesh& mesh, double x0, double y0, double w, double h, int nx, int ny, double z, bool down = false,
              const std::vector<std::pair<int, int>>& skip = {}) {
  std::map<std::array<double, 3>, std::uint32_t> index;
  for (std::uint32_t v = 0; v < mesh.positions.size(); ++v)
    index[{mesh.positions[v].x(), mesh.positions[v].y(), mesh.positions[v].z()}] = v;
  auto at = [&](int i, int j) {
    const Vec3 p(x0 + w * i / nx, y0 + h * j / ny, z);
    const auto [it, added] = index.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, static_cast<std::uint32_t>(mesh.positions.size()));
    if (added) mesh.positions.push_back(p);
    return it->second;
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (std::find(skip.begin(), skip.end(), std::pair{i, j}) != skip.end()) continue;
      const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if (down) {
        mesh.triangles.push_back({a, c, b});
        mesh.triangles.push_back({a, d, c});
      } else {
        mesh.triangles.push_back({a, b, c});
        mesh.triangles.push_back({a, c, d});
      }
    }
}

// The 2 x 1 rectangle in z = 0: its left unit square as one quad, its right one as two quads
// stacked, so the two halves meet at a T-junction (the vertex (1, 0.5)) and share no edge.
dg::TriangleMesh t_junction_rectangle() {
  dg::TriangleMesh mesh;
  add_grid(mesh, 0.0, 0.0, 1.0, 1.0, 1, 1, 0.0);
  add_grid(mesh, 1.0, 0.0, 1.0, 1.0, 1, 2, 0.0);
  return mesh;
}

std::vector<char> all(const dg::TriangleMesh& mesh) { return std::vector<char>(mesh.triangles.size(), 1); }

double length(const std::vector<std::array<Vec3, 2>>& outline) {
  double total = 0.0;
  for (const auto& s : outline) total += (s[1] - s[0]).norm();
  return total;
}

}  // namespace

TEST_CASE("flat regions: faces meeting at a T-junction are one region with the union's outline", "[geometry][flat_regions]") {
  dg::TriangleMesh mesh = t_junction_rectangle();
  add_grid(mesh, 0.0, 0.0, 1.0, 1.0, 1, 1, 0.5);  // another plane
  const std::vector<dg::FlatRegion> regions = dg::flat_regions(mesh, all(mesh));
  REQUIRE(regions.size() == 2);
  const dg::FlatRegion& rectangle = regions[0];
  CHECK(rectangle.triangles.size() == 6);
  CHECK(rectangle.area == Approx(2.0));
  CHECK(rectangle.normal.isApprox(Vec3::UnitZ()));
  // The outline is the rectangle's border (6 long), none of it along the line x = 1 inside.
  CHECK(length(rectangle.outline) == Approx(6.0));
  for (const auto& s : rectangle.outline) CHECK_FALSE((s[0].x() == 1.0 && s[1].x() == 1.0));
  CHECK(regions[1].area == Approx(1.0));
  // Only faces holding a flagged triangle: the upper square alone.
  std::vector<char> upper(mesh.triangles.size(), 0);
  upper.back() = 1;
  const std::vector<dg::FlatRegion> only = dg::flat_regions(mesh, upper);
  REQUIRE(only.size() == 1);
  CHECK(only[0].triangles == std::vector<std::uint32_t>{6, 7});
}

TEST_CASE("flat regions: materials and sides stay apart", "[geometry][flat_regions]") {
  dg::TriangleMesh mesh = t_junction_rectangle();
  mesh.materials = {0, 0, 1, 1, 1, 1};  // the right half painted differently
  CHECK(dg::flat_regions(mesh, all(mesh)).size() == 2);
  dg::TriangleMesh sides;
  add_grid(sides, 0.0, 0.0, 1.0, 1.0, 1, 1, 0.0);
  add_grid(sides, 0.0, 0.0, 1.0, 1.0, 1, 1, 0.0, true);  // the back side
  CHECK(dg::flat_regions(sides, all(sides)).size() == 2);
}

TEST_CASE("flat regions: faces apart in one plane join only as coplanar, and a region moves with its mesh",
          "[geometry][flat_regions]") {
  dg::TriangleMesh mesh;
  add_grid(mesh, 0.0, 0.0, 1.0, 1.0, 2, 2, 0.0);
  add_grid(mesh, 1.0, 0.0, 1.0, 1.0, 1, 1, 0.0);  // shares two corners with the first
  add_grid(mesh, 3.0, 0.0, 1.0, 1.0, 1, 1, 0.0);  // apart
  CHECK(dg::flat_regions(mesh, all(mesh)).size() == 1);
  const std::vector<dg::FlatRegion> joined = dg::flat_regions(mesh, all(mesh), dg::FlatJoin::sharing_corners);
  REQUIRE(joined.size() == 2);
  CHECK(joined[0].area == Approx(2.0));
  CHECK(joined[1].area == Approx(1.0));
  // The region moved is the region of the moved mesh; not where it was.
  dg::RigidTransform motion;
  motion.rotation = Eigen::AngleAxisd(0.5, Vec3(0, 1, 1).normalized()).toRotationMatrix();
  motion.translation = Vec3(0.3, -2.0, 1.0);
  dg::TriangleMesh moved_mesh = mesh;
  for (Vec3& p : moved_mesh.positions) p = motion.apply(p);
  const std::vector<dg::FlatRegion> moved = dg::flat_regions(moved_mesh, all(moved_mesh), dg::FlatJoin::sharing_corners);
  REQUIRE(moved.size() == 2);
  CHECK(dg::same_flat_region(dg::moved_region(joined[0], mesh, motion), moved[0], 1e-6));
  CHECK_FALSE(dg::same_flat_region(joined[0], moved[0], 1e-6));
  CHECK_FALSE(dg::same_flat_region(dg::moved_region(joined[0], mesh, motion), moved[1], 1e-6));
}

TEST_CASE("same_flat_region: one region however triangulated, not with a hole, moved or turned over", "[geometry][flat_regions]") {
  const double distance = 0.017;
  dg::TriangleMesh two;
  add_grid(two, 0.0, 0.0, 2.0, 1.0, 1, 1, 0.0);
  const dg::TriangleMesh junction = t_junction_rectangle();
  dg::TriangleMesh fine;
  add_grid(fine, 0.0, 0.0, 2.0, 1.0, 20, 10, 0.0);
  dg::TriangleMesh holed;  // a 0.1 x 0.1 hole in the middle
  add_grid(holed, 0.0, 0.0, 2.0, 1.0, 20, 10, 0.0, false, {{10, 5}});
  dg::TriangleMesh moved;
  add_grid(moved, 2.0 * distance, 0.0, 2.0, 1.0, 1, 1, 0.0);
  dg::TriangleMesh back;
  add_grid(back, 0.0, 0.0, 2.0, 1.0, 1, 1, 0.0, true);
  auto region = [](const dg::TriangleMesh& mesh) {
    const std::vector<dg::FlatRegion> regions = dg::flat_regions(mesh, all(mesh));
    REQUIRE(regions.size() == 1);
    return regions[0];
  };
  CHECK(dg::same_flat_region(region(two), region(junction), distance));
  CHECK(dg::same_flat_region(region(fine), region(two), distance));
  CHECK_FALSE(dg::same_flat_region(region(holed), region(fine), distance));
  CHECK_FALSE(dg::same_flat_region(region(fine), region(holed), distance));
  CHECK_FALSE(dg::same_flat_region(region(two), region(moved), distance));
  CHECK_FALSE(dg::same_flat_region(region(two), region(back), distance));
  // same_surface sees the hole too (the regions differ, so their cells are compared).
  CHECK(dg::same_surface(fine, junction, 2.0 * distance));
  CHECK_FALSE(dg::same_surface(fine, holed, 2.0 * distance));
  CHECK_FALSE(dg::same_surface(holed, fine, 2.0 * distance));
}
