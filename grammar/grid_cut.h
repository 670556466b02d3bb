#pragma once
// Cutting a model into the pieces of a grid rule: along every plane of every direction, each
// triangle (or point) going to the slab it lies in, and the slabs grouped by class (head,
// repeated unit, tail) per direction into the pieces resize places (paper 001 §3.4.3: r11 ..
// r33 for a 2-grid).

#include "geometry/mesh.h"
#include "grammar/grid_rules.h"

#include <cstddef>
#include <string>
#include <vector>

namespace dg {

/// Class of a slab along one direction (slab 0 lies before the first plane, slab count + 1 after
/// the last): 0 = head (slabs 0 .. head_units), 1 = the repeated unit (slab head_units + 1),
/// 2 = tail (the last tail_units units and slab count + 1); -1 = a copy of the unit, not stored.
int slab_class(std::size_t slab, const GridDirection& direction);

/// The mesh cut along every plane of a grid, with each triangle's slab along each direction:
/// slabs[t][i] is 0 before the first plane of direction i, k after plane k-1 (k = 1 .. count
/// are the units), count + 1 after the last plane (the tail).
struct GridCut {
  TriangleMesh mesh;
  std::vector<std::vector<std::size_t>> slabs;
};

/// Cuts `mesh` along the planes of every direction of `grid` (vertices within 1e-6 eps of a
/// plane are moved onto it). Each flat face of `mesh` (edge-joined triangles of one material in
/// one plane within 1e-6 eps) is then re-triangulated per cell, keeping the vertices of `mesh`
/// and only those cut vertices where cell borders turn or meet an edge between faces, so the
/// copies of a unit meet at the same seam vertices wherever the exemplar repeats. Back-to-back
/// double faces (the same corners in both orders, one material) are cut once and doubled, so
/// they stay exact doubles. Every triangle keeps the material of the triangle it was cut from.
GridCut cut_along_grid(const TriangleMesh& mesh, const GridRule& grid, double eps);

/// A piece of a grid: the triangles (or, for a point-cloud exemplar, the points) whose slab
/// classes along the directions are `classes`.
struct GridPiece {
  std::vector<int> classes;  ///< one of 0 (head), 1 (unit), 2 (tail) per direction
  TriangleMesh mesh;         ///< empty for a point-cloud exemplar
  PointCloud points;         ///< a point-cloud exemplar's points in the piece (normals when it had them)
};

/// Cuts the cleaned model into the pieces of `grid` (classes with no triangles are left out).
/// Piece names follow the paper: r11 .. r33 for a 2-grid (1 = head, 2 = unit, 3 = tail).
std::vector<GridPiece> cut_grid_pieces(const TriangleMesh& mesh, const GridRule& grid, double eps);

/// Slab of a point along `direction` (as GridCut::slabs counts them): the number of its planes at
/// or below the point, 0 .. count + 1.
std::size_t slab_of_point(const GridDirection& direction, const Vec3& point);

/// Cuts a point cloud into the pieces of `grid`: each point (with its normal) goes to the slab
/// it lies in along every direction, a point on a plane to the slab after it. Classes with no
/// points are left out; names and classes as for cut_grid_pieces.
std::vector<GridPiece> cut_grid_points(const PointCloud& cloud, const GridRule& grid);

/// "r" followed by 1-based classes, e.g. {0, 1} -> "r12".
std::string piece_name(const std::vector<int>& classes);

}  // namespace dg
