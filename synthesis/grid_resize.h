#pragma once
// Resizing a grid: head pieces once, the repeated unit count times, tail pieces shifted to
// the end, in every direction of the grid (corners once, borders along one direction, the
// interior along all), welded into one mesh.

#include "grammar/grid_rules.h"

#include <vector>

namespace dg {

/// Seam vertices of a resized grid weld (and split the other side's edges) within this
/// fraction of the voxel size eps. Copies meet where T^k and T^(k+1) place the two sides of a
/// cut, which agree only as well as T was fitted and the exemplar repeats itself: about 1e-6 of
/// the coordinates for float32 sources (the corpus pallet: 1.2e-6 model units, 2.5e-6 eps), so
/// 1e-6 eps left such seams open; features on a seam are far larger (eps / 100 and up).
inline constexpr double kSeamWeldFraction = 1e-4;

/// Assembles the pieces of `grid` for `counts` (one per direction, within the grid's count
/// range), welds vertices closer than `weld_tolerance` (model units) and re-triangulates the flat
/// faces the seams split (merge_flat_faces). Counts equal to the
/// grid's own counts reproduce the exemplar. Every triangle keeps its piece triangle's material
/// when all pieces carry materials (the result has none otherwise). Throws InputError when a count is out of range
/// (below a direction's min_units or the grid's range) or the number of counts does not match
/// the grid's dimension.
TriangleMesh resize_grid(const GridRule& grid, const std::vector<GridPiece>& pieces, const std::vector<int>& counts,
                         double weld_tolerance);

/// Assembles the points of a point-cloud grammar's grid pieces for `counts`, each piece placed
/// as resize_grid places its triangles (normals turned with it when every piece has them; no
/// welding: points have no seams). Throws as resize_grid.
PointCloud resize_grid_points(const GridRule& grid, const std::vector<GridPiece>& pieces, const std::vector<int>& counts);

}  // namespace dg
