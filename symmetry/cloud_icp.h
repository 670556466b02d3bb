#pragma once
// Point-to-plane ICP of a point cloud onto its own fitted cell planes: refines a candidate
// symmetry of a cloud on all its points, which pins a pitch far better than a few keypoints.

#include "geometry/mesh.h"
#include "geometry/rigid_transform.h"
#include "geometry/voxel_surface.h"

namespace dg {

struct CloudIcpOptions {
  std::size_t max_samples = 30000;  ///< evenly strided cloud points used per iteration
  double max_angle_degrees = 10.0;  ///< a mapped point's plane and its partner's agree within this
  /// Pairing distance per iteration (eps): wide first to catch a pitch off by a voxel, then
  /// narrow so that only surfaces that really coincide pull.
  std::vector<double> cutoffs_eps = {1.5, 1.0, 0.6, 0.3, 0.3, 0.3};
};

/// Refines t: each sampled point x, on a plane of its own cell (within 0.3 eps), is mapped to
/// t(x) and paired with the nearest plane of the cell holding t(x) whose normal matches the
/// mapped one (up to sign); one Gauss-Newton step per iteration minimizes the squared
/// point-to-plane distances. Directions the pairs do not constrain (a slide along a wall)
/// are left unchanged. Returns t when too few pairs are found. Deterministic.
RigidTransform refine_on_points(const PointCloud& cloud, const VoxelSurface& surface, const RigidTransform& t,
                                const CloudIcpOptions& options = {});

}  // namespace dg
