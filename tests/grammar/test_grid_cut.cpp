// Cutting a mesh into grid pieces: only the cut planes add vertices, and flat faces come back
// as few triangles as the cells allow, so resized grids stay close to the exemplar's size.

#include "grammar/grid_cut.h"
#include "grammar/grid_rules.h"

#include "geometry/topology.h"
#include "support/shapes.h"
#include "synthesis/grid_resize.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <set>

using dg::Vec3;

namespace {

// A 1-grid along x with unit pitch and planes x = 0.5 .. count + 0.5.
dg::GridRule bar_grid(int count) {
  dg::GridDirection d;
  d.motion.translation = Vec3(1, 0, 0);
  d.translation = Vec3(1, 0, 0);
  d.direction = Vec3::UnitX();
  d.pitch = 1.0;
  d.cut = 0.5;
  d.count = count;
  dg::GridRule grid;
  grid.name = "grid1";
  grid.directions = {d};
  return grid;
}

}  // namespace

TEST_CASE("grid cut: a long bar's faces come back as one quad per cell", "[grammar][grid]") {
  // The bar [0, 10] x [0, 1] x [0, 1]: 12 triangles, its four long faces cross all 10 planes.
  const dg::TriangleMesh bar = dg::test::make_box(Vec3(0, 0, 0), Vec3(10, 1, 1));
  const dg::GridRule grid = bar_grid(9);
  const dg::GridCut cut = dg::cut_along_grid(bar, grid, 0.1);
  // 11 cells, each with four long faces of two triangles; the end cells add their end caps.
  CHECK(cut.mesh.triangles.size() == 11 * 8 + 2 * 2);
  CHECK(cut.mesh.positions.size() == 8 + 10 * 4);  // the corners and four per plane, no unused one
  CHECK(cut.mesh.area() == Approx(bar.area()).epsilon(1e-12));
  CHECK(dg::is_closed_and_oriented(cut.mesh));
  const std::vector<dg::GridPiece> pieces = dg::cut_grid_pieces(bar, grid, 0.1);
  REQUIRE(pieces.size() == 3);
  CHECK(pieces[1].mesh.triangles.size() == 8);  // the unit
  // Copies meet at the same vertices (no T-junction to split), so the resized bar's long faces
  // are flat faces split only by seams: merged again, any count gives a box of 12 triangles.
  for (const int count : {9, 12}) {
    CAPTURE(count);
    const dg::TriangleMesh resized = dg::resize_grid(grid, pieces, {count}, 0.1);
    CHECK(resized.triangles.size() == 12);
    CHECK(resized.positions.size() == 8);
    CHECK(dg::is_closed_and_oriented(resized));
    CHECK(resized.area() == Approx(4.0 * (count + 1) + 2.0).epsilon(1e-12));
  }
}

TEST_CASE("grid cut: a back-to-back double face is cut alike on both sides", "[grammar][grid]") {
  // A long rectangle in z = 0 and the same rectangle facing down, on the same vertices.
  dg::TriangleMesh sheet;
  sheet.positions = {{0, 0, 0}, {10, 0, 0}, {10, 1, 0}, {0, 1, 0}};
  sheet.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 2, 1}, {0, 3, 2}};
  const dg::GridCut cut = dg::cut_along_grid(sheet, bar_grid(9), 0.1);
  // One quad per cell on each side.
  CHECK(cut.mesh.triangles.size() == 11 * 2 * 2);
  CHECK(cut.mesh.area() == Approx(sheet.area()).epsilon(1e-12));
  std::multiset<std::array<std::uint32_t, 3>> up, down;
  for (std::size_t t = 0; t < cut.mesh.triangles.size(); ++t) {
    std::array<std::uint32_t, 3> corners{cut.mesh.triangles[t][0], cut.mesh.triangles[t][1], cut.mesh.triangles[t][2]};
    std::sort(corners.begin(), corners.end());
    (cut.mesh.area_vector(t).z() > 0.0 ? up : down).insert(corners);
  }
  CHECK(up == down);
}
