// Edge topology with a counting sort: undirected edges are bucketed by their lower vertex
// index (CSR layout), so no map per edge is needed and 1M triangles take a few tens of ms.

#include "geometry/topology.h"

#include "geometry/union_find.h"

#include <algorithm>
#include <numeric>

namespace dg {

namespace {

/// Number of vertex slots the triangles need (at least positions.size()).
std::size_t vertex_slots(const TriangleMesh& mesh) {
  std::size_t slots = mesh.positions.size();
  for (const Triangle& t : mesh.triangles) {
    for (std::uint32_t index : t) slots = std::max<std::size_t>(slots, std::size_t{index} + 1);
  }
  return slots;
}

}  // namespace

EdgeStatistics edge_statistics(const TriangleMesh& mesh) {
  // Bucket every directed triangle edge (a, b), a != b, under min(a, b); the entry stores
  // max(a, b) shifted left by one plus a bit telling whether it ran from low to high.
  const std::size_t slots = vertex_slots(mesh);
  std::vector<std::size_t> start(slots + 1, 0);
  for (const Triangle& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
      if (a != b) ++start[std::min(a, b) + 1];
    }
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::uint64_t> entries(start.back());
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (const Triangle& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
      if (a == b) continue;
      const std::uint32_t low = std::min(a, b), high = std::max(a, b);
      entries[fill[low]++] = (std::uint64_t{high} << 1) | (a == low ? 1u : 0u);
    }
  }

  EdgeStatistics stats;
  for (std::size_t v = 0; v < slots; ++v) {
    const auto first = entries.begin() + static_cast<std::ptrdiff_t>(start[v]);
    const auto last = entries.begin() + static_cast<std::ptrdiff_t>(start[v + 1]);
    std::sort(first, last);
    for (auto run = first; run != last;) {
      auto end = run;
      std::size_t forward = 0;
      while (end != last && (*end >> 1) == (*run >> 1)) forward += (*end++ & 1u);
      const auto uses = static_cast<std::size_t>(end - run);
      ++stats.edges;
      if (uses == 1) ++stats.boundary_edges;
      if (uses >= 3) ++stats.non_manifold_edges;
      if (uses == 2 && forward != 1) ++stats.inconsistent_edges;
      run = end;
    }
  }
  return stats;
}

bool is_closed_and_oriented(const TriangleMesh& mesh) {
  const EdgeStatistics stats = edge_statistics(mesh);
  return stats.edges > 0 && stats.boundary_edges == 0 && stats.non_manifold_edges == 0 &&
         stats.inconsistent_edges == 0;
}

std::vector<std::uint32_t> triangle_components(const TriangleMesh& mesh, std::size_t* component_count) {
  const std::size_t slots = vertex_slots(mesh);
  std::vector<std::uint32_t> parent(slots);
  std::iota(parent.begin(), parent.end(), 0u);
  for (const Triangle& t : mesh.triangles) {
    for (int k = 1; k < 3; ++k) {
      const std::uint32_t a = find_root(parent, t[0]);
      const std::uint32_t b = find_root(parent, t[static_cast<std::size_t>(k)]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  }
  constexpr std::uint32_t unassigned = ~std::uint32_t{0};
  std::vector<std::uint32_t> id_of_root(slots, unassigned);
  std::vector<std::uint32_t> component(mesh.triangles.size());
  std::uint32_t next_id = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::uint32_t root = find_root(parent, mesh.triangles[t][0]);
    if (id_of_root[root] == unassigned) id_of_root[root] = next_id++;
    component[t] = id_of_root[root];
  }
  if (component_count) *component_count = next_id;
  return component;
}

VertexTriangles vertex_triangles(const TriangleMesh& mesh) {
  VertexTriangles around;
  around.first.assign(mesh.positions.size() + 1, 0);
  for (const Triangle& tri : mesh.triangles)
    for (std::uint32_t v : tri) ++around.first[v + 1];
  std::partial_sum(around.first.begin(), around.first.end(), around.first.begin());
  around.triangles.resize(around.first.back());
  std::vector<std::uint32_t> filled(around.first.begin(), around.first.end() - 1);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::uint32_t v : mesh.triangles[t]) around.triangles[filled[v]++] = t;
  return around;
}

EdgeUsers edge_users(const TriangleMesh& mesh) {
  std::vector<std::pair<std::uint64_t, std::uint32_t>> uses;  // edge key, corner 3t + k
  uses.reserve(3 * mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const auto [lo, hi] = std::minmax(mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3]);
      uses.push_back({(static_cast<std::uint64_t>(lo) << 32) | hi, static_cast<std::uint32_t>(3 * t + k)});
    }
  std::sort(uses.begin(), uses.end());
  EdgeUsers users;
  users.corners.resize(uses.size());
  users.group_begin.resize(uses.size());
  users.group_end.resize(uses.size());
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].first == uses[i].first) ++j;
    for (std::size_t u = i; u < j; ++u) {
      users.corners[u] = uses[u].second;
      users.group_begin[uses[u].second] = static_cast<std::uint32_t>(i);
      users.group_end[uses[u].second] = static_cast<std::uint32_t>(j);
    }
    i = j;
  }
  return users;
}

}  // namespace dg
