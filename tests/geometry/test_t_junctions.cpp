// Closing seams whose sides were triangulated differently (T-junctions), and open-edge flags.

#include "geometry/t_junctions.h"

#include "geometry/topology.h"

#include <catch2/catch.hpp>

#include <algorithm>

using dg::Vec3;

namespace {

// Two unit squares in the plane z = 0 meeting along x = 1: the left one as two triangles,
// the right one as three, with an extra vertex at (1, 0.5 + shift) on the shared side.
dg::TriangleMesh squares_with_t_junction(double shift) {
  dg::TriangleMesh mesh;
  mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),                          // left
                    Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(1, 1, 0), Vec3(1, 0.5 + shift, 0)};  // right
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 8}, {8, 5, 6}, {8, 6, 7}};
  return mesh;
}

}  // namespace

TEST_CASE("T-junction on a seam: the long edge is split and the seam closes", "[geometry][t_junctions]") {
  for (const bool with_flags : {false, true}) {
    CAPTURE(with_flags);
    dg::TriangleMesh mesh = squares_with_t_junction(1e-9);
    const std::vector<char> open = dg::open_edge_vertices(mesh);
    // Every vertex of these two open squares lies on an open edge.
    CHECK(std::count(open.begin(), open.end(), 1) == 9);
    const std::size_t splits = dg::resolve_t_junctions(mesh, 1e-6, with_flags ? &open : nullptr);
    CHECK(splits == 1);
    CHECK(mesh.positions.size() == 7);  // (1, 0) and (1, 1) welded
    CHECK(mesh.triangles.size() == 6);
    const dg::EdgeStatistics edges = dg::edge_statistics(mesh);
    CHECK(edges.boundary_edges == 6);  // only the outer rectangle stays open
    CHECK(edges.non_manifold_edges == 0);
    CHECK(edges.inconsistent_edges == 0);
    CHECK(mesh.area() == Approx(2.0));
  }
}

TEST_CASE("T-junction farther than the tolerance stays open", "[geometry][t_junctions]") {
  dg::TriangleMesh mesh = squares_with_t_junction(0.0);
  for (Vec3& p : mesh.positions)
    if (p.x() == 1.0 && p.y() == 0.5) p.x() += 1e-3;
  CHECK(dg::resolve_t_junctions(mesh, 1e-6) == 0);
  CHECK(dg::edge_statistics(mesh).boundary_edges == 9);
}

TEST_CASE("open edge vertices of a closed box and of a box without one face", "[geometry][t_junctions]") {
  dg::TriangleMesh box;
  box.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)};
  box.triangles = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                   {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  REQUIRE(dg::is_closed_and_oriented(box));
  const std::vector<char> closed = dg::open_edge_vertices(box);
  CHECK(std::count(closed.begin(), closed.end(), 1) == 0);
  box.triangles.erase(box.triangles.begin() + 2, box.triangles.begin() + 4);  // the top face z = 1
  CHECK(dg::open_edge_vertices(box) == std::vector<char>{0, 0, 0, 0, 1, 1, 1, 1});
}

TEST_CASE("a sliver whose third corner lies on its own open edge is dropped, not split", "[geometry][t_junctions]") {
  // The sliver a b c has c on its open edge a b; the triangle a c d beside it. Splitting a b at
  // c would give the parts a c c and c b c: triangles with a repeated corner.
  dg::TriangleMesh mesh;
  mesh.positions = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0)};
  enum : std::uint32_t { a, b, c, d };
  mesh.triangles = {{a, b, c}, {a, c, d}};
  mesh.materials = {0, 1};
  CHECK(dg::resolve_t_junctions(mesh, 1e-9) == 1);
  REQUIRE(mesh.triangles.size() == 1);
  CHECK(mesh.triangles[0] == dg::Triangle{a, c, d});
  CHECK(mesh.materials == std::vector<std::uint32_t>{1});
  CHECK(dg::edge_statistics(mesh).boundary_edges == 3);
}
