// Flat faces of a mesh, and re-triangulating them after cuts and assembly split them.

#include "geometry/flat_faces.h"

#include "geometry/topology.h"
#include "geometry/zone_cut.h"

#include <catch2/catch.hpp>

#include <set>

using dg::Vec3;

namespace {

// The unit cube, 12 outward-facing triangles, diced by the planes x, y, z = 0.25, 0.5, 0.75.
dg::TriangleMesh diced_cube() {
  dg::TriangleMesh cube;
  cube.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
                    Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)};
  cube.triangles = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                    {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  std::vector<dg::PlaneFamily> families{{Vec3::UnitX(), {0.25, 0.5, 0.75}}, {Vec3::UnitY(), {0.25, 0.5, 0.75}},
                                        {Vec3::UnitZ(), {0.25, 0.5, 0.75}}};
  return dg::cut_zone(cube, std::vector<char>(12, 1), families, 1e-9).mesh;
}

}  // namespace

TEST_CASE("flat faces: a diced cube has six", "[geometry][flat_faces]") {
  const dg::TriangleMesh cube = diced_cube();
  REQUIRE(cube.triangles.size() > 12 * 16);
  const std::vector<std::uint32_t> face = dg::flat_faces(cube, {}, 1e-9);
  CHECK(std::set<std::uint32_t>(face.begin(), face.end()).size() == 6);
  // The kind flag splits them: one flag for the triangles with x < 0.5 splits the four sides
  // that cross x = 0.5 in two.
  std::vector<char> kind(cube.triangles.size());
  for (std::size_t t = 0; t < kind.size(); ++t) {
    const auto [a, b, c] = cube.corners(t);
    kind[t] = (a + b + c).x() / 3.0 < 0.5;
  }
  const std::vector<std::uint32_t> split = dg::flat_faces(cube, kind, 1e-9);
  CHECK(std::set<std::uint32_t>(split.begin(), split.end()).size() == 10);
}

TEST_CASE("flat faces: merging gives back the cube's 12 triangles, closed and outward", "[geometry][flat_faces]") {
  const dg::TriangleMesh merged = dg::merge_flat_faces(diced_cube());
  CHECK(merged.triangles.size() == 12);
  CHECK(merged.positions.size() == 8);  // unused vertices removed
  CHECK(merged.area() == Approx(6.0).epsilon(1e-12));
  CHECK(dg::is_closed_and_oriented(merged));
  for (std::size_t t = 0; t < merged.triangles.size(); ++t) {
    const auto [a, b, c] = merged.corners(t);
    CHECK(merged.area_vector(t).dot((a + b + c) / 3.0 - Vec3(0.5, 0.5, 0.5)) > 0.0);  // faces outward
  }
}

TEST_CASE("flat faces: material borders, bends and open edges keep their vertices", "[geometry][flat_faces]") {
  dg::TriangleMesh cube = diced_cube();
  // Paint the triangles with x < 0.5 in a second material: the border x = 0.5 on the four sides
  // that cross it stays (4 vertices of it on each side, corners included, all shared).
  cube.materials.assign(cube.triangles.size(), 0);
  for (std::size_t t = 0; t < cube.triangles.size(); ++t) {
    const auto [a, b, c] = cube.corners(t);
    cube.materials[t] = (a + b + c).x() / 3.0 < 0.5 ? 1 : 0;
  }
  const dg::TriangleMesh painted = dg::merge_flat_faces(cube);
  CHECK(painted.positions.size() == 12);  // the 8 corners and the 4 where x = 0.5 meets the cube's edges
  CHECK(painted.triangles.size() == 20);  // 2 on each end, 4 on each crossed side (two rectangles)
  CHECK(dg::is_closed_and_oriented(painted));
  REQUIRE(painted.has_materials());
  for (std::size_t t = 0; t < painted.triangles.size(); ++t) {
    const auto [a, b, c] = painted.corners(t);
    CHECK(painted.materials[t] == ((a + b + c).x() / 3.0 < 0.5 ? 1u : 0u));
  }
  // Without its top face the cube is open: the vertices along the open rim stay.
  dg::TriangleMesh open = diced_cube();
  std::erase_if(open.triangles, [&](const dg::Triangle& t) {
    return open.positions[t[0]].z() == 1.0 && open.positions[t[1]].z() == 1.0 && open.positions[t[2]].z() == 1.0;
  });
  const dg::TriangleMesh merged_open = dg::merge_flat_faces(open);
  const dg::EdgeStatistics edges = dg::edge_statistics(merged_open);
  CHECK(edges.boundary_edges == 16);  // the rim keeps its 16 cut pieces
  CHECK(edges.non_manifold_edges == 0);
  CHECK(merged_open.area() == Approx(5.0).epsilon(1e-12));
}

TEST_CASE("flat faces: a face with a crack inside keeps its triangles and its open edges", "[geometry][flat_faces]") {
  // The rectangle [0, 4] x [0, 2] as a left strip, a right strip and a middle split at y = 1 by a
  // crack: below it the edge has a vertex at (2, 1), above it not (a T-junction, as messy models
  // have). The strips join the halves into one flat face. Re-triangulating it from its outline
  // would close the crack, a change of which edges are open that other parts of a messy model
  // (a twin face, a part ending on the crack) do not follow.
  dg::TriangleMesh face;
  face.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(1, 2, 0), Vec3(0, 2, 0), Vec3(3, 0, 0),
                    Vec3(3, 1, 0), Vec3(2, 1, 0), Vec3(3, 2, 0), Vec3(4, 0, 0), Vec3(4, 2, 0)};
  enum : std::uint32_t { A, B, C, D, E, G, H, M, I, J, K };
  face.triangles = {{A, B, C}, {A, C, E}, {C, D, E},  // left strip
                    {B, G, M}, {G, H, M}, {B, M, C},  // below the crack
                    {C, H, I}, {C, I, D},             // above it
                    {G, J, H}, {H, J, K}, {H, K, I}}; // right strip
  const dg::EdgeStatistics before = dg::edge_statistics(face);
  const dg::TriangleMesh merged = dg::merge_flat_faces(face);
  CHECK(merged.triangles.size() == face.triangles.size());
  CHECK(dg::edge_statistics(merged).boundary_edges == before.boundary_edges);
  CHECK(merged.area() == Approx(8.0).epsilon(1e-12));
}

TEST_CASE("flat faces: a part standing on a line across a face keeps the face's triangles", "[geometry][flat_faces]") {
  // A flat kite A B C D fanned around its centre c, and a fin standing on its short diagonal B D
  // (the diagonal its re-triangulation would take). The fin's foot runs through c, a line the
  // face's own triangles do not follow: messy models have such parts. Re-triangulated, the face
  // would use B D as an edge too, a non-manifold edge with the fin's.
  dg::TriangleMesh mesh;
  mesh.positions = {Vec3(0, 0, 0), Vec3(1, -0.3, 0), Vec3(2, 0, 0), Vec3(1, 0.3, 0), Vec3(1, 0, 0), Vec3(1, 0, 1)};
  enum : std::uint32_t { A, B, C, D, c, top };
  mesh.triangles = {{A, B, c}, {B, C, c}, {C, D, c}, {D, A, c}, {B, D, top}};
  const dg::TriangleMesh merged = dg::merge_flat_faces(mesh);
  CHECK(merged.triangles.size() == 5);
  CHECK(dg::edge_statistics(merged).non_manifold_edges == 0);
  // Without the fin, the kite merges into two triangles.
  mesh.triangles.pop_back();
  CHECK(dg::merge_flat_faces(mesh).triangles.size() == 2);
}

TEST_CASE("flat faces: each side of a double-sided face is one face and merges", "[geometry][flat_faces]") {
  // The unit square held twice, front (up) and back (down), diced 4 x 4: every cut edge inside
  // has four users, two per side (game assets draw thin gates and fences so).
  dg::TriangleMesh square;
  square.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  square.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 2, 1}, {0, 3, 2}};
  const std::vector<dg::PlaneFamily> families{{Vec3::UnitX(), {0.25, 0.5, 0.75}}, {Vec3::UnitY(), {0.25, 0.5, 0.75}}};
  const dg::TriangleMesh diced = dg::cut_zone(square, std::vector<char>(4, 1), families, 1e-9).mesh;
  REQUIRE(diced.triangles.size() > 4 * 8);
  const std::vector<std::uint32_t> face = dg::flat_faces(diced, {}, 1e-9);
  CHECK(std::set<std::uint32_t>(face.begin(), face.end()).size() == 2);
  const dg::TriangleMesh merged = dg::merge_flat_faces(diced);
  CHECK(merged.triangles.size() == 4);
  CHECK(merged.area() == Approx(2.0).epsilon(1e-12));
  double facing = 0.0;
  for (std::size_t t = 0; t < merged.triangles.size(); ++t) facing += merged.area_vector(t).z();
  CHECK(facing == Approx(0.0).margin(1e-12));  // two triangles up, two down
}
