#include "geometry/cell_pieces.h"

#include "geometry/prepared_model.h"
#include "support/shapes.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numeric>
#include <set>

using dg::Vec3;

namespace {

// Key of a cell: 1 for voxels whose centre lies in the slab 1 < x < 2 of the box, else 0.
std::vector<std::uint32_t> band_keys(const dg::VoxelSurface& surface) {
  std::vector<std::uint32_t> keys(surface.cell_count(), 0);
  for (std::uint32_t c = 0; c < surface.cell_count(); ++c) keys[c] = surface.centre(c).x() > 1.0 && surface.centre(c).x() < 2.0 ? 1 : 0;
  return keys;
}

}  // namespace

TEST_CASE("cell keys: triangles stay whole where their cells agree and are cut along key borders only",
          "[geometry][pictures]") {
  // A 3 x 1 x 1 box of 12 large triangles on a voxel grid of 0.1 (about 140 cells per face).
  dg::Model model;
  model.mesh = dg::test::make_box(Vec3(0, 0, 0), Vec3(3, 1, 1));
  dg::PrepareOptions options;
  options.r = 0.4;
  options.eps = 0.1;
  const dg::PreparedModel prepared = dg::prepare_model(std::move(model), options);
  const dg::TriangleMesh& mesh = prepared.model.mesh;
  const dg::VoxelSurface& surface = prepared.surface;

  std::vector<std::uint32_t> keys;
  const dg::TriangleMesh same = dg::cut_where_cell_keys_differ(mesh, surface, std::vector<std::uint32_t>(surface.cell_count(), 7), keys);
  CHECK(same.triangles.size() == mesh.triangles.size());
  CHECK(std::set<std::uint32_t>(keys.begin(), keys.end()) == std::set<std::uint32_t>{7});
  CHECK(same.area() == Approx(mesh.area()).epsilon(1e-12));

  const dg::TriangleMesh banded = dg::cut_where_cell_keys_differ(mesh, surface, band_keys(surface), keys);
  REQUIRE(keys.size() == banded.triangles.size());
  CHECK(banded.area() == Approx(mesh.area()).epsilon(1e-12));  // no piece lost, none twice
  double band_area = 0.0;
  for (std::size_t t = 0; t < banded.triangles.size(); ++t) {
    const auto [a, b, c] = banded.corners(t);
    const double area = 0.5 * banded.area_vector(t).norm();
    if (area < 1e-15) continue;
    const double x = (a.x() + b.x() + c.x()) / 3.0;
    CHECK(keys[t] == (x > 1.0 && x < 2.0 ? 1u : 0u));
    if (keys[t] == 1) band_area += area;
  }
  // The band's voxels reach from x = 1.0 to 2.0: four faces of 1 x 1 each.
  CHECK(band_area == Approx(4.0).epsilon(1e-9));
  // Only the long faces' triangles cross the key borders, and each is cut into a few runs,
  // not into its ~150 cells: far fewer triangles than one piece per cell.
  std::vector<std::uint32_t> cell_indices(surface.cell_count()), cells;
  std::iota(cell_indices.begin(), cell_indices.end(), 0u);
  const dg::TriangleMesh per_cell = dg::cut_where_cell_keys_differ(mesh, surface, cell_indices, cells);
  CHECK(per_cell.area() == Approx(mesh.area()).epsilon(1e-12));
  CHECK(banded.triangles.size() * 10 < per_cell.triangles.size());
  // Vertices are shared only within one key.
  std::vector<std::set<std::uint32_t>> vertex_keys(banded.positions.size());
  for (std::size_t t = 0; t < banded.triangles.size(); ++t)
    for (std::uint32_t v : banded.triangles[t]) vertex_keys[v].insert(keys[t]);
  for (const auto& k : vertex_keys) CHECK(k.size() <= 1);
}
