#pragma once
// Comparing one r-neighbourhood of a candidate with the exemplar under a rigid motion T
// (candidate -> exemplar): the both-ways surface test, and point-to-plane ICP that refines T.

#include "geometry/rigid_transform.h"
#include "synthesis/r_similarity_index.h"

#include <cstdint>
#include <span>
#include <vector>

namespace dg {

struct MatchTolerances {
  double r = 1.0;          ///< neighbourhood radius, model units
  /// Largest distance of a mapped sample from the other surface, model units (<= max_cutoff of the indexes).
  double tolerance = 0.0;
  double min_cos = 0.0;  ///< cosine of the largest angle between a mapped normal and the surface normal
  /// ICP pairs a sample with surface at most this far away, model units (<= max_cutoff of the indexes).
  double icp_cutoff = 0.0;
  int icp_iterations = 10;
  /// Fraction of a ball's samples (each way) allowed to miss the other surface: 0 for meshes;
  /// point clouds leave random gaps at edges and corners that no disk radius closes for sure.
  double max_missing_fraction = 0.0;
};

/// True when the neighbourhoods match under t: every candidate sample of `ball` (y's intrinsic
/// r-neighbourhood, SurfaceIndex::gather_connected) mapped by t touches the exemplar, and every
/// sample of the exemplar's intrinsic r-neighbourhood of t(y) mapped back by t^-1 touches the
/// candidate (distance and normal tolerances; up to max_missing_fraction of each side may
/// miss); false when no exemplar element lies within the tolerance of t(y). `scratch` is
/// reused storage.
bool neighbourhoods_match(const SurfaceIndex& candidate, const SurfaceIndex& exemplar, const SurfacePoint& y,
                          std::span<const std::uint32_t> ball, const RigidTransform& t, const MatchTolerances& tolerances,
                          std::vector<std::uint32_t>& scratch);

/// Refines t by point-to-plane ICP of the candidate samples `ball` against the exemplar's
/// triangles (pairs within icp_cutoff with compatible normals; rotations about t(y)).
/// Directions the geometry leaves free (slides along planes and edges) stay as they were.
RigidTransform refine_alignment(const SurfaceIndex& candidate, const SurfaceIndex& exemplar, const Vec3& y,
                                std::span<const std::uint32_t> ball, RigidTransform t, const MatchTolerances& tolerances);

}  // namespace dg
