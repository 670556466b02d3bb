#pragma once
// The voxel surface (paper 001 §4): every voxel of edge length eps that the surface touches,
// each mapped to a cell holding the exact geometry inside it. Symmetric regions, erosion and
// docking sites are all computed on this graph of cells.
//
// Convention: voxel (i, j, k) is the CLOSED box [i, i+1] x [j, j+1] x [k, k+1] times eps in
// model units (grid origin at the model origin), so a face lying on a voxel plane touches the
// voxels on both sides. Cells are numbered in lexicographic (i, j, k) order.

#include "geometry/feature_edges.h"
#include "geometry/feature_lines.h"
#include "geometry/mesh.h"
#include "geometry/progress.h"

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace dg {

/// Integer voxel coordinates (i, j, k).
using VoxelCoord = std::array<std::int32_t, 3>;

/// Oriented plane n . x = offset (n unit, pointing to the front of the triangles it came from).
/// `material` is the material index of the triangles on it (0 when the mesh has none or the
/// surface was built without VoxelSurfaceOptions::separate_materials): planes of different
/// materials stay apart, so symmetry must map each material onto itself.
/// `bend_degrees` is how far the surface turns from its triangles to their smooth neighbours
/// (tessellation_bend.h): 0 on flat geometry, the tessellation step on a faceted curve.
struct CellPlane {
  Vec3 normal = Vec3::UnitZ();
  double offset = 0.0;
  std::uint32_t material = 0;
  double bend_degrees = 0.0;
};

/// Infinite line through `point` with unit `direction`, from a feature or boundary edge.
/// `bend_degrees`: how far the feature polyline turns at the ends of its edges (0 when straight).
struct CellLine {
  Vec3 point = Vec3::Zero();
  Vec3 direction = Vec3::UnitX();
  EdgeKind kind = EdgeKind::sharp;
  double bend_degrees = 0.0;
};

/// Radius r from paper 001: 1.6 % of the longest bounding-box side.
double default_radius(const BoundingBox& bounds);

/// Whether every point of `bounds` lies within the voxel grid's reach at voxel size `eps`
/// (fewer than 2^20 - 2 voxels from the origin along each axis).
bool within_voxel_reach(const BoundingBox& bounds, double eps);

struct VoxelSurfaceOptions {
  double r = 0.0;    ///< similarity radius in model units; 0 = default_radius(bounds)
  double eps = 0.0;  ///< voxel edge length in model units; 0 = r / 4
  /// Planes of triangles in one cell merge when their normals differ by less than this (degrees)
  double plane_merge_angle_degrees = 1.0;
  /// ... and their offsets differ by less than this fraction of eps.
  double plane_merge_offset = 0.05;
  /// Feature polylines turning by less than this at a vertex tessellate a curve, and their edges
  /// get a bend (CellLine::bend_degrees); larger turns are corners.
  double corner_angle_degrees = kDefaultCornerAngleDegrees;
  /// Empty: every cell plane has material 0. Else the matching class of each material index
  /// (material_classes()): cell planes keep the class of their triangles (CellPlane::material).
  std::vector<std::uint32_t> material_classes;
};

/// Counts for reports.
struct VoxelSurfaceStats {
  std::size_t voxels = 0;       ///< occupied voxels = cells
  std::size_t planes = 0;       ///< merged planes over all cells
  std::size_t lines = 0;        ///< merged feature/boundary lines over all cells
  std::size_t points = 0;       ///< point-cloud points over all cells
  std::size_t memory_bytes = 0; ///< approximate memory held by the surface
};

class VoxelSurface {
 public:
  VoxelSurface();
  ~VoxelSurface();
  VoxelSurface(VoxelSurface&&) noexcept;
  VoxelSurface& operator=(VoxelSurface&&) noexcept;

  double r() const { return r_; }      ///< similarity radius, model units
  double eps() const { return eps_; }  ///< voxel edge length, model units
  std::size_t cell_count() const { return coords_.size(); }

  /// Voxel coordinates of a cell.
  const VoxelCoord& coord(std::uint32_t cell) const { return coords_[cell]; }
  /// Centre of a cell's voxel in model units.
  Vec3 centre(std::uint32_t cell) const;
  /// Voxel containing model-space point p (half-open rounding: floor(p / eps)).
  VoxelCoord voxel_of(const Vec3& p) const;
  /// Cell index of a voxel, or -1 when the voxel holds no surface (OpenVDB lookup, thread-safe).
  std::int64_t find(const VoxelCoord& voxel) const;

  /// Exact geometry inside a cell.
  std::span<const CellPlane> planes(std::uint32_t cell) const { return slice(planes_, plane_offsets_, cell); }
  std::span<const CellLine> lines(std::uint32_t cell) const { return slice(lines_, line_offsets_, cell); }
  /// Triangle indices (mesh input) overlapping the cell, ascending.
  std::span<const std::uint32_t> triangles(std::uint32_t cell) const { return slice(triangles_, triangle_offsets_, cell); }
  /// Point indices (point-cloud input) inside the cell, ascending.
  std::span<const std::uint32_t> points(std::uint32_t cell) const { return slice(points_, point_offsets_, cell); }
  /// Surface area inside the cell's closed voxel (model units^2; for point clouds an estimate:
  /// eps^2 per occupied voxel on average, shared out by point count). A face lying
  /// exactly on a voxel plane counts in both voxels; use fractions of total_area().
  double area(std::uint32_t cell) const { return areas_[cell]; }
  /// Sum of area() over all cells.
  double total_area() const { return total_area_; }
  /// Occupied 26-neighbours of a cell, ascending cell index.
  std::span<const std::uint32_t> neighbours(std::uint32_t cell) const { return slice(neighbours_, neighbour_offsets_, cell); }

  /// Connected component per cell over 26-adjacency, numbered by lowest cell; count via out-param.
  std::vector<std::uint32_t> components(std::size_t* component_count = nullptr) const;

  /// Intrinsic distance from the nearest source cell to every cell (model units): shortest paths
  /// on the 26-neighbourhood graph with edge lengths eps, sqrt(2) eps, sqrt(3) eps. Cells farther
  /// than max_distance (or unreachable) get +infinity. With `passable` (one flag per cell), paths
  /// only enter cells whose flag is non-zero (sources are always reached).
  std::vector<double> intrinsic_distance(std::span<const std::uint32_t> sources,
                                         double max_distance = std::numeric_limits<double>::infinity(),
                                         const std::vector<char>* passable = nullptr) const;

  VoxelSurfaceStats stats() const;

 private:
  template <class T>
  static std::span<const T> slice(const std::vector<T>& data, const std::vector<std::uint32_t>& offsets,
                                  std::uint32_t cell) {
    if (offsets.empty()) return {};
    return std::span<const T>(data.data() + offsets[cell], offsets[cell + 1] - offsets[cell]);
  }

  friend class VoxelSurfaceBuilder;
  struct Grid;  // OpenVDB index grid, hidden from users of this header

  double r_ = 0.0, eps_ = 0.0;
  std::vector<VoxelCoord> coords_;
  std::vector<std::uint32_t> plane_offsets_, line_offsets_, triangle_offsets_, point_offsets_, neighbour_offsets_;
  std::vector<CellPlane> planes_;
  std::vector<CellLine> lines_;
  std::vector<std::uint32_t> triangles_, points_, neighbours_;
  std::vector<double> areas_;
  double total_area_ = 0.0;
  std::unique_ptr<Grid> grid_;
};

/// Builds the voxel surface of a welded mesh. `features` (from find_feature_edges) supply the
/// cell lines. Parallel (TBB) and deterministic: the result is independent of the thread count.
/// Throws InputError when the mesh is empty or the grid would exceed 2^20 voxels per axis.
VoxelSurface build_voxel_surface(const TriangleMesh& mesh, const std::vector<FeatureEdge>& features,
                                 const VoxelSurfaceOptions& options = {}, const ProgressCallback& progress = {});

/// Builds the voxel surface of a point cloud: each point lies in the voxel floor(p / eps); cell
/// planes (unoriented normals) and crease lines are fitted to the points (fit_cloud_cells).
VoxelSurface build_voxel_surface(const PointCloud& cloud, const VoxelSurfaceOptions& options = {},
                                 const ProgressCallback& progress = {});

}  // namespace dg
