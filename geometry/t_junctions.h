#pragma once
// Closing seams whose two sides were triangulated differently: a vertex of one side lying on
// an edge of the other (a T-junction) splits that edge, so the seam becomes shared edges.

#include "geometry/mesh.h"

namespace dg {

/// Splits every boundary edge at the boundary vertices lying on it (within `tolerance` model
/// units, strictly between its ends), then welds vertices closer than `tolerance`. Returns the
/// number of edge splits. Assembled pieces whose seams coincide geometrically become closed. A
/// sliver whose third corner lies on its own split edge has no area and is dropped.
/// With `seam_vertices` (one flag per vertex: the vertices on the open edges of the assembled
/// pieces), only those are welded and only edges between them are examined, which is much
/// faster on large assemblies and gives the same result when the flags cover every open edge.
std::size_t resolve_t_junctions(TriangleMesh& mesh, double tolerance, const std::vector<char>* seam_vertices = nullptr);

/// One flag per vertex of `mesh`: 1 when the vertex lies on an open edge (an edge used by one
/// triangle only). Pieces' flags, concatenated, are the `seam_vertices` of their assembly.
std::vector<char> open_edge_vertices(const TriangleMesh& mesh);

}  // namespace dg
