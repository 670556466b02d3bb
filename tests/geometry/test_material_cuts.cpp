// Cutting keeps materials: every piece carries the material of the triangle it was cut from,
// and re-triangulation never joins fragments of different materials.

#include "geometry/cell_pieces.h"
#include "geometry/fragment_merge.h"
#include "geometry/prepared_model.h"
#include "geometry/slab_cut.h"
#include "geometry/zone_cut.h"
#include "grammar/grid_cut.h"
#include "grammar/grid_rules.h"
#include "support/shapes.h"

#include <catch2/catch.hpp>

#include <numeric>

using dg::Vec3;

namespace {

// The wall [0, 4] x [0, 1] in z = 0 as 4 unit squares of 2 triangles: x < 2 is material 0
// ("brick"), x > 2 material 1 ("glass").
dg::TriangleMesh two_material_wall() {
  dg::TriangleMesh wall;
  for (int i = 0; i <= 4; ++i) wall.positions.push_back(Vec3(i, 0, 0)), wall.positions.push_back(Vec3(i, 1, 0));
  for (std::uint32_t i = 0; i < 4; ++i) {
    const std::uint32_t a = 2 * i, b = a + 2, c = a + 3, d = a + 1;
    wall.triangles.push_back({a, b, c});
    wall.triangles.push_back({a, c, d});
    wall.materials.insert(wall.materials.end(), 2, i < 2 ? 0u : 1u);
  }
  return wall;
}

Vec3 centroid(const dg::TriangleMesh& mesh, std::size_t t) {
  const auto [a, b, c] = mesh.corners(t);
  return (a + b + c) / 3.0;
}

// Every triangle carries the wall's material where it lies, with all its corners on that
// material's side of x = 2; for the whole wall (`whole`) the area of each material is 2.
void check_wall_materials(const dg::TriangleMesh& mesh, bool whole = true) {
  REQUIRE(mesh.has_materials());
  std::array<double, 2> area{0.0, 0.0};
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::uint32_t expected = centroid(mesh, t).x() < 2.0 ? 0 : 1;
    INFO("triangle " << t << " centroid " << centroid(mesh, t).transpose());
    CHECK(mesh.materials[t] == expected);
    for (const Vec3& p : mesh.corners(t)) CHECK((expected == 0 ? p.x() <= 2.0 + 1e-12 : p.x() >= 2.0 - 1e-12));
    area[mesh.materials[t]] += 0.5 * mesh.area_vector(t).norm();
  }
  if (!whole) return;
  CHECK(area[0] == Approx(2.0).epsilon(1e-12));
  CHECK(area[1] == Approx(2.0).epsilon(1e-12));
}

}  // namespace

TEST_CASE("materials: plane and zone cuts give each piece its triangle's material", "[geometry][materials]") {
  const dg::TriangleMesh wall = two_material_wall();
  const dg::TriangleMesh sliced = dg::cut_along_planes(wall, Vec3(1, 1, 0).normalized(), {0.5, 1.5, 2.5}, 1e-9);
  CHECK(sliced.triangles.size() > wall.triangles.size());
  check_wall_materials(sliced);

  dg::PlaneFamily x{Vec3::UnitX(), {0.25, 1.75, 2.5}}, y{Vec3::UnitY(), {0.3, 0.6}};
  const std::vector<char> zone = {1, 1, 0, 0, 1, 0, 1, 1};
  const dg::ZoneCut cut = dg::cut_zone(wall, zone, {x, y}, 1e-9);
  CHECK(cut.mesh.triangles.size() > wall.triangles.size());
  check_wall_materials(cut.mesh);
  for (std::size_t t = 0; t < cut.mesh.triangles.size(); ++t) CHECK(cut.mesh.materials[t] == wall.materials[cut.origin[t]]);

  // Without materials the cuts make none.
  dg::TriangleMesh plain = wall;
  plain.materials.clear();
  CHECK(dg::cut_along_planes(plain, Vec3::UnitX(), {0.5}, 1e-9).materials.empty());
  CHECK(dg::cut_zone(plain, zone, {x}, 1e-9).mesh.materials.empty());
}

TEST_CASE("materials: a flat wall of two materials is re-triangulated as two regions", "[geometry][materials]") {
  // All fragments share one origin and label: only the material keeps the halves apart.
  const dg::TriangleMesh wall = two_material_wall();
  dg::PlaneFamily x{Vec3::UnitX(), {}};
  for (int k = 1; k < 16; ++k) x.offsets.push_back(0.25 * k);
  const dg::ZoneCut cut = dg::cut_zone(wall, std::vector<char>(wall.triangles.size(), 1), {x}, 1e-9);
  std::vector<char> pinned(cut.mesh.positions.size(), 0);
  std::fill(pinned.begin(), pinned.begin() + static_cast<std::ptrdiff_t>(wall.positions.size()), 1);  // the wall's corners
  const std::vector<std::uint32_t> one(cut.mesh.triangles.size(), 0);
  const dg::MergedFragments merged = dg::merge_fragments(cut.mesh, one, one, pinned, {.straighten_label_borders = true});
  CHECK(merged.mesh.triangles.size() < cut.mesh.triangles.size());
  check_wall_materials(merged.mesh);

  // The grid cut joins a flat face's fragments per cell, but not across materials.
  dg::GridDirection d;
  d.motion.translation = d.translation = Vec3(1, 0, 0);
  d.direction = Vec3::UnitX();
  d.pitch = 1.0;
  d.cut = 0.5;
  d.count = 3;
  dg::GridRule grid;
  grid.directions = {d};
  const dg::GridCut grid_cut = dg::cut_along_grid(wall, grid, 0.1);
  check_wall_materials(grid_cut.mesh);
  for (const dg::GridPiece& piece : dg::cut_grid_pieces(wall, grid, 0.1)) check_wall_materials(piece.mesh, false);
}

TEST_CASE("materials: cell pieces keep the material of their triangle", "[geometry][materials]") {
  // A box whose top face is material 1 and the rest material 0.
  dg::Model model;
  model.mesh = dg::test::make_box(Vec3(0, 0, 0), Vec3(2, 1, 1));
  for (std::size_t t = 0; t < model.mesh.triangles.size(); ++t)
    model.mesh.materials.push_back(centroid(model.mesh, t).z() > 1.0 - 1e-12 ? 1 : 0);
  model.materials = {{"wall", Vec3(0.8, 0.8, 0.8)}, {"roof", Vec3(0.6, 0.1, 0.1)}};
  const dg::PreparedModel prepared = dg::prepare_model(std::move(model));
  REQUIRE(prepared.model.mesh.has_materials());
  std::vector<std::uint32_t> cell_indices(prepared.surface.cell_count()), cells;
  std::iota(cell_indices.begin(), cell_indices.end(), 0u);
  const dg::TriangleMesh pieces = dg::cut_where_cell_keys_differ(prepared.model.mesh, prepared.surface, cell_indices, cells);
  REQUIRE(pieces.has_materials());
  double roof = 0.0;
  for (std::size_t t = 0; t < pieces.triangles.size(); ++t) {
    // Fans of clipped polygons may hold zero-area triangles, which face nowhere: skipped.
    if (pieces.area_vector(t).norm() < 1e-15) continue;
    const bool on_top = centroid(pieces, t).z() > 1.0 - 1e-12 && pieces.area_vector(t).z() > 0.0;
    CHECK(pieces.materials[t] == (on_top ? 1u : 0u));
    if (pieces.materials[t] == 1) roof += 0.5 * pieces.area_vector(t).norm();
  }
  CHECK(roof == Approx(2.0).epsilon(1e-9));
}
