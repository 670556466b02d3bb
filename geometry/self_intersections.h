#pragma once
// Self-intersections of a triangle mesh: pairs of triangles that share a point other than a
// common vertex or a common edge (exact predicates; CGAL is hidden in the .cpp).

#include "geometry/mesh.h"

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace dg {

struct SelfIntersectionOptions {
  /// Enumeration stops after this many intersecting pairs (0 = only decide yes/no).
  std::size_t max_pairs = 1000;
};

struct SelfIntersections {
  /// Intersecting triangle index pairs (first < second), ascending; at most max_pairs.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  bool any = false;     ///< at least one intersecting pair exists
  bool capped = false;  ///< the enumeration stopped at max_pairs (more pairs may exist)
  /// Vertices were duplicated at non-manifold spots to build a halfedge mesh; triangles that
  /// touch only at such a vertex are then counted as intersecting.
  bool non_manifold_input = false;
};

/// Finds self-intersecting triangle pairs of a welded mesh (see clean_mesh; degenerate
/// triangles must already be dropped). Triangles sharing a vertex index may still intersect
/// elsewhere (e.g. folded over); those pairs are reported. Parallel (TBB); the result is
/// deterministic unless it is capped, when the set of reported pairs may vary.
SelfIntersections find_self_intersections(const TriangleMesh& mesh, const SelfIntersectionOptions& options = {});

}  // namespace dg
