#pragma once
// Closing seams whose two sides were triangulated differently: a vertex of one side lying on
// an edge of the other (a T-junction) splits that edge, so the seam becomes shared edges.

#include "geometry/mesh.h"
#include "geometry/vertex_weld.h"

namespace dg {

/// Splits every boundary edge at the boundary vertices lying on it (within `tolerance` model
/// units, strictly between its ends), then welds vertices closer than `tolerance`. Returns the
/// number of edge splits. Assembled pieces whose seams coincide geometrically become closed. A
/// sliver whose third corner lies on its own split edge has no area and is dropped.
/// With `seam_copies` (one label per vertex: the placed copy of a piece whose open edge the
/// vertex lies on, kNotOnSeam for the other vertices, see append_seam_labels), only seam vertices
/// are welded, each to the nearest within `tolerance` that does not face away from it and that
/// no vertex of its own copy joined unless within `same_copy_tolerance` (two parts that touch stay
/// apart, as in the piece; see weld_vertices); an open edge is split at a vertex on the same
/// terms (its triangle's normal against the vertex's); and only edges between seam vertices are
/// examined, which is much faster on large assemblies.
std::size_t resolve_t_junctions(TriangleMesh& mesh, double tolerance, const std::vector<std::uint32_t>* seam_copies = nullptr,
                                double same_copy_tolerance = 0.0);

/// Closes every hole bounded by exactly three open edges whose perimeter is at most
/// `max_perimeter` (model units) with one triangle, oriented like its neighbours (material of the
/// triangle on its first edge). Such slivers are left where a weld joined a seam vertex to a near
/// neighbour of its partner instead of the partner itself. Returns the number of holes closed.
std::size_t close_triangular_holes(TriangleMesh& mesh, double max_perimeter);

/// Drops every triangle hanging by one edge off an edge that three or more triangles use, its
/// two other edges open, when its third corner lies within `tolerance` (model units) of that
/// edge: a sliver left where a weld kept a seam vertex apart from the one it should have joined
/// (its edge then has its two proper users besides). Triangles with a repeated corner go too.
/// Returns the number of slivers dropped.
std::size_t drop_hanging_slivers(TriangleMesh& mesh, double tolerance);

/// One flag per vertex of `mesh`: 1 when the vertex lies on an open edge (an edge used by one
/// triangle only). append_seam_labels turns a placed copy's flags into seam labels.
std::vector<char> open_edge_vertices(const TriangleMesh& mesh);

/// Appends the seam labels of one placed copy of a piece to `labels`: `copy` for the vertices
/// flagged in `open` (open_edge_vertices of the piece), kNotOnSeam for the others.
void append_seam_labels(std::vector<std::uint32_t>& labels, const std::vector<char>& open, std::uint32_t copy);

}  // namespace dg
