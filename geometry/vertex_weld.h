#pragma once
// Merging vertices that lie within a distance of each other. Assemblies of pieces (grid copies,
// placed terminals) label each vertex with the copy it came from, so that vertices of one copy,
// apart in the piece, stay apart in the assembly.

#include "geometry/mesh.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace dg {

/// Label of a vertex that a labelled weld keeps as it is (it lies on no seam).
inline constexpr std::uint32_t kNotOnSeam = std::numeric_limits<std::uint32_t>::max();

/// Merges vertices within `tolerance` (model units), in index order, and drops triangles that
/// become degenerate (the others keep their materials). Without `copies`, each vertex joins the
/// first earlier kept vertex found within `tolerance`. With `copies` (one label per vertex),
/// vertices labelled kNotOnSeam are kept as they are, and each other vertex joins the nearest
/// earlier kept vertex within `tolerance` whose surface does not face away from its own (their
/// vertex normals, see vertex_normals, at most 90 degrees apart: the seams of a leg's top and of
/// the seat's underside it touches stay apart) and that no vertex of its own copy joined, or that
/// lies within `same_copy_tolerance`: touching parts of one copy stay apart, its duplicate
/// vertices merge. A vertex of its copy that is its neighbour along an open edge (a seam edge of the
/// copy) does not count: such an edge, shorter than the tolerance, collapses when both its ends
/// lie nearest to one vertex (kept, the second end would fold back across the first). Returns
/// the new index of every old vertex. Deterministic.
std::vector<std::uint32_t> weld_vertices(TriangleMesh& mesh, double tolerance,
                                         const std::vector<std::uint32_t>* copies = nullptr,
                                         double same_copy_tolerance = 0.0);

}  // namespace dg
