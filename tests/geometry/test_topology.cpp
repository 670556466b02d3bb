// Edge statistics, closedness and triangle components.

#include "geometry/topology.h"

#include <catch2/catch.hpp>

using dg::Triangle;
using dg::TriangleMesh;
using dg::Vec3;

namespace {

/// Closed, outward-oriented box with 8 vertices and 12 triangles, offset by `shift`.
TriangleMesh box(const Vec3& shift) {
  TriangleMesh mesh;
  const Vec3 corners[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (const Vec3& c : corners) mesh.positions.push_back(c + shift);
  const std::uint32_t quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};
  for (const auto& q : quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[2], q[3]});
  }
  return mesh;
}

/// Regular grid of n x n quads (2 n^2 triangles) in the plane z = 0.
TriangleMesh grid(std::uint32_t n) {
  TriangleMesh mesh;
  for (std::uint32_t y = 0; y <= n; ++y) {
    for (std::uint32_t x = 0; x <= n; ++x) mesh.positions.emplace_back(x, y, 0);
  }
  mesh.triangles.reserve(2 * std::size_t{n} * n);
  for (std::uint32_t y = 0; y < n; ++y) {
    for (std::uint32_t x = 0; x < n; ++x) {
      const std::uint32_t a = y * (n + 1) + x;
      mesh.triangles.push_back({a, a + 1, a + n + 2});
      mesh.triangles.push_back({a, a + n + 2, a + n + 1});
    }
  }
  return mesh;
}

}  // namespace

TEST_CASE("a box is closed and oriented", "[geometry][topology]") {
  const TriangleMesh mesh = box(Vec3::Zero());
  const dg::EdgeStatistics stats = dg::edge_statistics(mesh);
  CHECK(stats.edges == 18);
  CHECK(stats.boundary_edges == 0);
  CHECK(stats.non_manifold_edges == 0);
  CHECK(stats.inconsistent_edges == 0);
  CHECK(dg::is_closed_and_oriented(mesh));
  CHECK_FALSE(dg::is_closed_and_oriented(TriangleMesh{}));
}

TEST_CASE("a flipped triangle gives inconsistent edges, a missing one boundary edges", "[geometry][topology]") {
  TriangleMesh flipped = box(Vec3::Zero());
  std::swap(flipped.triangles[3][1], flipped.triangles[3][2]);
  CHECK(dg::edge_statistics(flipped).inconsistent_edges == 3);
  CHECK_FALSE(dg::is_closed_and_oriented(flipped));

  TriangleMesh open = box(Vec3::Zero());
  open.triangles.pop_back();
  const dg::EdgeStatistics stats = dg::edge_statistics(open);
  CHECK(stats.boundary_edges == 3);
  CHECK(stats.edges == 18);
  CHECK_FALSE(dg::is_closed_and_oriented(open));
}

TEST_CASE("three triangles on an edge make it non-manifold", "[geometry][topology]") {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const dg::EdgeStatistics stats = dg::edge_statistics(mesh);
  CHECK(stats.edges == 7);
  CHECK(stats.non_manifold_edges == 1);
  CHECK(stats.boundary_edges == 6);
  CHECK(stats.inconsistent_edges == 0);
}

TEST_CASE("components are vertex-connected and numbered by lowest triangle", "[geometry][topology]") {
  TriangleMesh a = box(Vec3::Zero());
  const TriangleMesh b = box(Vec3(5, 0, 0));
  // Interleave: triangle 0 from b, then all of a, then the rest of b.
  TriangleMesh mesh;
  mesh.positions = a.positions;
  mesh.positions.insert(mesh.positions.end(), b.positions.begin(), b.positions.end());
  auto shifted = [](Triangle t) { return Triangle{t[0] + 8, t[1] + 8, t[2] + 8}; };
  mesh.triangles.push_back(shifted(b.triangles[0]));
  mesh.triangles.insert(mesh.triangles.end(), a.triangles.begin(), a.triangles.end());
  for (std::size_t t = 1; t < b.triangles.size(); ++t) mesh.triangles.push_back(shifted(b.triangles[t]));
  std::size_t count = 0;
  const std::vector<std::uint32_t> component = dg::triangle_components(mesh, &count);
  CHECK(count == 2);
  CHECK(component[0] == 0);
  CHECK(component[1] == 1);
  CHECK(component[12] == 1);
  CHECK(component[13] == 0);
  CHECK(component.back() == 0);

  TriangleMesh touching;  // two triangles sharing only vertex 0
  touching.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  touching.triangles = {{0, 1, 2}, {0, 3, 4}};
  dg::triangle_components(touching, &count);
  CHECK(count == 1);
}

TEST_CASE("edge statistics of a million-triangle grid", "[geometry][topology]") {
  const std::uint32_t n = 708;  // 1,002,528 triangles
  const TriangleMesh mesh = grid(n);
  const dg::EdgeStatistics stats = dg::edge_statistics(mesh);
  const std::size_t m = n;
  CHECK(stats.edges == 2 * m * (m + 1) + m * m);
  CHECK(stats.boundary_edges == 4 * m);
  CHECK(stats.non_manifold_edges == 0);
  CHECK(stats.inconsistent_edges == 0);
  std::size_t count = 0;
  dg::triangle_components(mesh, &count);
  CHECK(count == 1);
}
