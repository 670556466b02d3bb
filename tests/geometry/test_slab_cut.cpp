// Cutting meshes along parallel planes (grid pieces).

#include "geometry/slab_cut.h"

#include "assets/generator/asset.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>
#include <set>

namespace {

std::set<std::array<std::uint32_t, 3>> vertex_sets(const std::vector<dg::Triangle>& triangles) {
  std::set<std::array<std::uint32_t, 3>> sets;
  for (dg::Triangle t : triangles) {
    std::sort(t.begin(), t.end());
    sets.insert({t[0], t[1], t[2]});
  }
  return sets;
}

}  // namespace

TEST_CASE("cutting a back-to-back double face splits both faces alike", "[geometry][slab_cut]") {
  // Both orders of the corners, and both ways round the two far corners' indices.
  for (const bool far_corners_swapped : {false, true}) {
    CAPTURE(far_corners_swapped);
    dg::TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}};
    if (far_corners_swapped) std::swap(mesh.positions[1], mesh.positions[2]);
    mesh.triangles = {{0, 1, 2}, {0, 2, 1}};
    // The plane x = 1 leaves corner 0 alone on its side: each face becomes a triangle and a quad
    // split in two.
    const dg::TriangleMesh cut = dg::cut_along_planes(mesh, dg::Vec3::UnitX(), {1.0}, 1e-9);
    REQUIRE(cut.triangles.size() == 6);
    const std::vector<dg::Triangle> front(cut.triangles.begin(), cut.triangles.begin() + 3);
    const std::vector<dg::Triangle> back(cut.triangles.begin() + 3, cut.triangles.end());
    CHECK(vertex_sets(front) == vertex_sets(back));
    CHECK(cut.area() == Approx(mesh.area()).epsilon(1e-12));
  }
}

TEST_CASE("cutting reports the input triangle of every piece", "[geometry][slab_cut]") {
  // A long rectangle (two triangles) across nine planes.
  dg::TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {10, 0, 0}, {10, 1, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  std::vector<double> cuts;
  for (int k = 1; k <= 9; ++k) cuts.push_back(k);
  std::vector<std::uint32_t> origin{7, 3};
  const dg::TriangleMesh cut = dg::cut_along_planes(mesh, dg::Vec3::UnitX(), cuts, 1e-9, &origin);
  REQUIRE(origin.size() == cut.triangles.size());
  std::array<double, 2> area{0.0, 0.0};
  for (std::size_t t = 0; t < cut.triangles.size(); ++t) {
    REQUIRE((origin[t] == 7 || origin[t] == 3));
    area[origin[t] == 7 ? 0 : 1] += cut.area_vector(t).norm() / 2.0;
  }
  CHECK(area[0] == Approx(5.0).epsilon(1e-12));
  CHECK(area[1] == Approx(5.0).epsilon(1e-12));
  // The input's vertices come first, unchanged.
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) CHECK(cut.positions[v] == mesh.positions[v]);
}

TEST_CASE("slab table: each slab's area and cut mesh agree with cutting the whole mesh at its planes",
          "[geometry][slab_cut]") {
  // A facade turned off the axes, so triangles cross the planes at every angle.
  dg::TriangleMesh mesh = dg::assets::make_asset("facade", {{"columns", 3}, {"rows", 2}}).mesh;
  const dg::Vec3 direction = dg::Vec3(1.0, 0.2, 0.35).normalized();
  const double start = 0.37, pitch = 1.3;
  const dg::SlabTable table(mesh, direction, start, pitch);
  double lowest = 1e300, highest = -1e300, total = 0.0;
  for (const dg::Vec3& p : mesh.positions) lowest = std::min(lowest, direction.dot(p)), highest = std::max(highest, direction.dot(p));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) total += 0.5 * mesh.area_vector(t).norm();
  const int first = static_cast<int>(std::floor((lowest - start) / pitch)) - 2;
  const int last = static_cast<int>(std::floor((highest - start) / pitch)) + 2;
  // Every plane at once: the slabs' triangles of this cut are the reference.
  std::vector<double> cuts;
  for (int k = first; k <= last + 1; ++k) cuts.push_back(start + k * pitch);
  const dg::TriangleMesh all = dg::cut_along_planes(mesh, direction, cuts, 0.0);
  std::vector<double> reference(cuts.size() + 1, 0.0);
  for (std::size_t t = 0; t < all.triangles.size(); ++t)
    reference[dg::slab_of(all, t, direction, cuts)] += 0.5 * all.area_vector(t).norm();
  double summed = 0.0;
  for (int k = first; k <= last; ++k) {
    CAPTURE(k);
    const double expected = reference[static_cast<std::size_t>(k - first + 1)];
    CHECK(table.area(k) == Approx(expected).margin(1e-9 * total));
    const dg::TriangleMesh slab = table.mesh(k, 0.0);
    double area = 0.0;
    for (std::size_t t = 0; t < slab.triangles.size(); ++t) {
      area += 0.5 * slab.area_vector(t).norm();
      for (const std::uint32_t v : slab.triangles[t]) {
        const double s = direction.dot(slab.positions[v]);
        CHECK(s >= start + k * pitch - 1e-9);
        CHECK(s <= start + (k + 1) * pitch + 1e-9);
      }
    }
    CHECK(area == Approx(expected).margin(1e-9 * total));
    summed += table.area(k);
  }
  CHECK(summed == Approx(total));
  CHECK(table.area(first - 5) == 0.0);
  CHECK(table.mesh(last + 5, 0.0).triangles.empty());
}
