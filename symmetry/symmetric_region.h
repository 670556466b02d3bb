#pragma once
// The symmetric region xi(T) of a candidate motion on the voxel surface, and its erosion by r
// in intrinsic distance, xi_r(T) (paper 001 §3.1, §4.1).

#include "geometry/mesh.h"
#include "geometry/rigid_transform.h"
#include "geometry/voxel_surface.h"

#include <cstdint>
#include <span>
#include <vector>

namespace dg {

struct RegionOptions {
  double angle_tolerance_degrees = 1.0;  ///< mapped planes/lines must agree in direction within this
  double offset_tolerance_eps = 0.1;     ///< ... and in position within this many eps
  /// Facets of a tessellated curve (a plane or line with a bend, see CellPlane) may instead land
  /// tilted by up to the angle tolerance plus their bend (at most `max_bend_degrees`), as long as
  /// they stay within `curved_deviation_eps` x eps of the facet they land on across the voxel:
  /// distance at the image of the cell centre + half the voxel diagonal x sin(tilt). A motion
  /// that does not share the tessellation step (a handrail in 8-degree segments under a
  /// 22.5-degree screw) maps such facets onto the curve, not onto its facets.
  double max_bend_degrees = 15.0;
  double curved_deviation_eps = 0.25;
  /// Point clouds compare fitted cell planes and creases, with these tolerances.
  double cloud_angle_tolerance_degrees = 3.0;
  double cloud_offset_tolerance_eps = 0.25;
};

/// The direction and position tolerances cells of a mesh or of a point cloud are matched with.
struct CellTolerances {
  double angle_degrees = 0.0;
  double offset_eps = 0.0;
};
CellTolerances cell_tolerances(const RegionOptions& options, bool point_cloud);

/// Cell of the voxel holding point p (model units), or the occupied voxel of the 3x3x3 block
/// around it whose centre is nearest (the first in x, y, z block order on ties); -1 if none.
std::int64_t nearest_cell(const VoxelSurface& surface, const Vec3& p);

/// Decides whether single cells are symmetric under a motion by comparing exact geometry.
class CellMatcher {
 public:
  /// `cloud` is the point cloud the surface was built from, or null for meshes (it selects the
  /// cloud tolerances). Plane normals are compared up to sign: a face with flipped orientation,
  /// or a back-to-back duplicate of it, lies on the same surface (common damage in real assets).
  CellMatcher(const VoxelSurface& surface, const PointCloud* cloud, const RegionOptions& options = {});

  /// True when every plane and line of `cell`, mapped by `t`, lies on geometry near the image
  /// of the cell centre. A point cloud's cell with two or more planes (a crease or corner, fitted
  /// to few points each) instead needs 80 % of its points, mapped, within the offset tolerance
  /// of a plane of the image cell or its 3x3x3 block.
  bool maps_onto_surface(std::uint32_t cell, const RigidTransform& t) const;

  /// Cell of the voxel holding t(centre(cell)), or the nearest occupied voxel around it; -1 if none.
  std::int64_t image_cell(std::uint32_t cell, const RigidTransform& t) const;

  /// The cells that `cells` cover once moved by `t`, as one flag per cell in `image`: the image
  /// cells of their centres, and the cells of the 3x3x3 blocks around those images whose own
  /// centres map back (under t^-1) into `cells`. Mapped centres alone leave holes where t does
  /// not carry the voxel grid onto itself (a pitch that is no multiple of eps, a model at an
  /// angle to the axes). Returns how many centres of `cells` map off the surface.
  std::size_t image_of_cells(std::span<const std::uint32_t> cells, const RigidTransform& t, std::vector<char>& image) const;

  /// Symmetric in both directions: the cell maps onto the surface under t, and its image cell
  /// maps back onto the surface under `inverse` (= t^-1).
  bool symmetric(std::uint32_t cell, const RigidTransform& t, const RigidTransform& inverse) const;

 private:
  /// Whether geometry with unit direction `a` (a normal, or a line direction), at `distance` from
  /// geometry with unit direction `b`, lies on it: exactly for flat geometry (`bend_degrees` no
  /// more than the angle tolerance), within the curved deviation for facets of curves.
  bool on_same_geometry(const Vec3& a, const Vec3& b, double distance, double bend_degrees) const;

  const VoxelSurface& surface_;
  double cos_tolerance_, offset_tolerance_;
  double angle_tolerance_degrees_, max_bend_degrees_, curved_deviation_;
  double half_diagonal_;  // of a voxel, model units
  const PointCloud* cloud_;  // null for meshes
};

struct SymmetricRegion {
  std::vector<std::uint32_t> symmetric_cells;    ///< xi(T), ascending
  std::vector<std::uint32_t> r_symmetric_cells;  ///< xi_r(T), ascending
  double symmetric_area = 0.0;                   ///< sum of cell areas, model units^2
  double r_symmetric_area = 0.0;
  std::size_t cells_tested = 0;
  bool rejected_early = false;
};

/// The connected parts of a voxel surface (26-adjacency) and about 8 cells spread over each,
/// for symmetric_region to grow into parts its seeds do not reach.
struct SurfaceParts {
  std::vector<std::uint32_t> part_of;               ///< part per cell
  std::vector<std::vector<std::uint32_t>> samples;  ///< per part, cells spread over it
};

/// Labels the parts of `surface` and picks their sample cells.
SurfaceParts surface_parts(const VoxelSurface& surface);

/// Grows xi(T) from `seeds` through 26-adjacent cells that pass CellMatcher::symmetric (cells
/// not connected to a seed through symmetric cells are not found), then, given `parts`, from the
/// sample cells of each part that growing did not reach (a table top apart from the chairs that
/// hold the seeds) when most of them pass, and erodes it: a cell stays in xi_r(T) when its
/// intrinsic distance to the nearest non-symmetric cell exceeds r.
/// Point clouds (`fill_outliers`): a failed cell whose neighbours are mostly symmetric counts
/// as symmetric (isolated outliers inside symmetric area), and so does a cluster of failed cells
/// (with the untested cells they enclose) that symmetric cells surround, when it has at most
/// the cells of a disk of diameter r (pi (r / 2 eps)^2). Early rejection: when fewer than a
/// quarter of the seeds (a tenth for point clouds) are symmetric, the candidate is bad and the
/// region is returned empty without growing.
SymmetricRegion symmetric_region(const CellMatcher& matcher, const VoxelSurface& surface, const RigidTransform& t,
                                 std::span<const std::uint32_t> seeds, bool fill_outliers,
                                 const SurfaceParts* parts = nullptr);

/// xi(T) with every cell of the surface tested in parallel (not only those connected to seeds),
/// and its erosion xi_r(T).
SymmetricRegion tested_symmetric_region(const CellMatcher& matcher, const VoxelSurface& surface, const RigidTransform& t);

/// Cells of `region` (ascending) whose intrinsic distance to any cell outside it exceeds r.
std::vector<std::uint32_t> erode(const VoxelSurface& surface, const std::vector<std::uint32_t>& region, double r);

}  // namespace dg
