#pragma once
// Keypoints of point clouds, which have no feature lines: corners where three fitted cell
// planes meet, one keypoint per crease that starts there, framed like a feature-line end.

#include "geometry/mesh.h"
#include "geometry/voxel_surface.h"
#include "symmetry/candidates.h"

#include <vector>

namespace dg {

struct CloudKeypointOptions {
  double min_corner_determinant = 0.3;  ///< |n_a . (n_b x n_c)| three planes need to make a corner
  double inlier_tolerance_eps = 0.25;   ///< a point lies on a plane within this many eps
  std::size_t min_side_points = 2;      ///< points each plane needs along a crease to show it there
  /// Planes of a cell and its neighbours within this angle (and the inlier tolerance) are one.
  double same_plane_degrees = 5.0;
};

/// Keypoints at the corners of a point cloud's voxel surface (built with fitted planes, see
/// fit_cloud_cells): for a cell holding three planes whose intersection point lies in its voxel,
/// each pair of the planes gives a crease through the corner. A cell holding two planes (scan
/// noise often leaves a corner's own cell without its third) tries each other plane of its
/// neighbours as the third (planes within same_plane_degrees and the inlier tolerance of one
/// already there count once). A crease that runs out of the corner on one side only (both
/// planes have points along it there, within two voxels) gives a keypoint at the corner:
/// tangent along the crease away from the corner, normal pointing away from the wedge between
/// the two half-planes, binormal = tangent x normal, and the wedge's opening angle as the
/// descriptor's dihedral. Deterministic, in cell order.
std::vector<Keypoint> cloud_keypoints(const PointCloud& cloud, const VoxelSurface& surface,
                                      const CloudKeypointOptions& options = {});

/// Samples along the creases of a point cloud's voxel surface, the cloud's counterpart of
/// feature-line samples: for each cell and each pair of its fitted planes meeting at more than
/// `min_crease_angle_degrees` whose line passes through the voxel, the point of that line
/// nearest the voxel's centre, framed like a keypoint (tangent along the line, normal away from
/// the wedge both planes' points show along it, dihedral = the wedge's opening angle). Cells
/// where a plane shows no points along the line are left out. Deterministic, in cell order.
std::vector<Keypoint> cloud_crease_samples(const PointCloud& cloud, const VoxelSurface& surface,
                                           const CloudKeypointOptions& options = {},
                                           double min_crease_angle_degrees = 20.0);

}  // namespace dg
