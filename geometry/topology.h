#pragma once
// Edge-based topology of an indexed triangle mesh: boundary and non-manifold edges,
// orientation consistency, connected components.

#include "geometry/mesh.h"

#include <cstddef>
#include <vector>

namespace dg {

/// Counts over the undirected edges of a mesh (edges identified by vertex indices).
struct EdgeStatistics {
  std::size_t edges = 0;               ///< distinct undirected edges
  std::size_t boundary_edges = 0;      ///< used by exactly one triangle
  std::size_t non_manifold_edges = 0;  ///< used by three or more triangles
  std::size_t inconsistent_edges = 0;  ///< manifold edges whose two triangles traverse it the same way
};

/// Edge counts of a mesh; indices must already be welded for the counts to mean anything.
EdgeStatistics edge_statistics(const TriangleMesh& mesh);

/// True when every edge has exactly two triangles traversing it in opposite directions.
bool is_closed_and_oriented(const TriangleMesh& mesh);

/// Component id per triangle: triangles sharing a vertex index are connected; components are
/// numbered in order of their lowest triangle index. Writes the number of components when asked.
std::vector<std::uint32_t> triangle_components(const TriangleMesh& mesh, std::size_t* component_count = nullptr);

/// Triangles around each vertex: triangles[first[v] .. first[v + 1]) are those using vertex v,
/// in index order (one using v twice is listed twice); first has one entry per vertex plus one.
struct VertexTriangles {
  std::vector<std::uint32_t> first;
  std::vector<std::uint32_t> triangles;
};

/// The triangles around each vertex of `mesh` (counting sort, O(vertices + triangles)).
VertexTriangles vertex_triangles(const TriangleMesh& mesh);

/// The triangles around every edge of a mesh, non-manifold edges included (real assets have
/// fins and back-to-back doubles, whose edges three or more triangles use).
struct EdgeUsers {
  /// Triangle corners 3t + k (edge from corner k to k + 1), grouped by edge.
  std::vector<std::uint32_t> corners;
  /// Per corner: its edge's group, corners[group_begin[c] .. group_end[c]).
  std::vector<std::uint32_t> group_begin, group_end;
};

/// The users of every edge of `mesh` (sorted edge keys, O(T log T)).
EdgeUsers edge_users(const TriangleMesh& mesh);

}  // namespace dg
