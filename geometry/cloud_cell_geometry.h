#pragma once
// Exact-geometry stand-ins for the cells of a point-cloud voxel surface: the planes the points
// of a cell lie on, and the creases where two of them meet inside the cell, so that cloud cells
// are compared like mesh cells (paper 001 §4: planes and lines per cell).

#include "geometry/mesh.h"
#include "geometry/voxel_surface.h"

#include <vector>

namespace dg {

struct CloudCellOptions {
  /// Surface variation lambda0 / (lambda0 + lambda1 + lambda2) of a cell's 3x3x3 block of
  /// points below which the block is one plane.
  double flat_variation = 0.005;
  std::size_t min_points = 6;           ///< points a block needs for a plane fit
  double min_inlier_tolerance_eps = 0.1;  ///< a point lies on a plane within max(this eps, 3 x noise)
  double min_crease_angle_degrees = 20.0; ///< two planes meeting at less than this give no crease
  std::size_t triple_trials = 80;       ///< planes through point triples tried per bent cell
  std::size_t min_plane_points = 5;     ///< block points a plane of a bent cell must hold
  double min_spread = 0.05;             ///< ... spread over an area: lambda1 / lambda2 of them above this
};

/// Planes and creases of one cell. Plane normals are unoriented (clouds carry no inside and
/// outside): each is flipped so its first clearly non-zero component is positive.
struct CloudCell {
  std::vector<CellPlane> planes;
  std::vector<CellLine> lines;
};

/// Fits every cell of `surface` (built from `cloud`, with points and neighbours set): a cell
/// whose 3x3x3 block is flat (small variation, or points no farther from the block's plane, root
/// mean square, than 1.2 times the scan's noise floor, the lower quartile of that over all
/// blocks; and every point within the inlier tolerance of the plane) gets that plane.
/// Otherwise candidate planes (of flat blocks within two rings, and through triples of nearby
/// block points) are chosen greedily by the block points they hold (at most four, each refitted
/// to its points, none whose points lie along a line), and those passing through the voxel are
/// kept (at most three), with a crease line for each pair meeting at more than
/// min_crease_angle_degrees whose intersection passes through the voxel. A cell with no such
/// plane gets the block's least-squares plane. Parallel, deterministic.
std::vector<CloudCell> fit_cloud_cells(const PointCloud& cloud, const VoxelSurface& surface,
                                       const CloudCellOptions& options = {});

/// A unit normal per point of `cloud` from the fitted planes of `surface` (built from it): the
/// plane of the point's cell it lies closest to. Creases keep each side's own normal, which a
/// fit to the point's nearest neighbours would blend. Signs as the planes' (unoriented).
std::vector<Vec3> cell_plane_normals(const PointCloud& cloud, const VoxelSurface& surface);

}  // namespace dg
