#pragma once
// Keypoints of point clouds, which have no feature lines: places where the sampled surface
// bends (creases and corners), with a frame from the local principal axes of the points.

#include "geometry/mesh.h"
#include "geometry/voxel_surface.h"
#include "symmetry/candidates.h"

#include <vector>

namespace dg {

struct CloudKeypointOptions {
  /// Surface variation lambda0 / (lambda0 + lambda1 + lambda2) of the points around a cell
  /// above which the surface bends there (a plane gives 0, a right-angled crease about 0.1).
  double min_variation = 0.03;
  double max_flat_variation = 0.01;  ///< cells below this variation are flat (their normal frames a bend)
  std::size_t min_points = 8;  ///< points a neighbourhood needs to be analysed
};

/// Keypoints at cells whose surface variation (points of the cell and its 26-neighbours) is a
/// local maximum over two rings of cells and above the threshold: corners where creases meet.
/// Position: the neighbourhood's centroid. Frame: from the normals of the flat cells within two
/// rings (turned away from the centroid of that wider neighbourhood, clustered within 15
/// degrees): normal = the largest cluster A, tangent = the next cluster B at least 30 degrees
/// away, made orthogonal to A; a second keypoint swaps A and B. The angle between A and B is
/// the descriptor's dihedral, so only similar bends are paired. Deterministic, in cell order.
std::vector<Keypoint> cloud_keypoints(const PointCloud& cloud, const VoxelSurface& surface,
                                      const CloudKeypointOptions& options = {});

}  // namespace dg
