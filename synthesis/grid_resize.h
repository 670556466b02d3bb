#pragma once
// Resizing a grid: head pieces once, the repeated unit count times, tail pieces shifted to
// the end, in every direction of the grid (corners once, borders along one direction, the
// interior along all), welded into one mesh.

#include "grammar/grid_cut.h"
#include "grammar/grid_seams.h"

#include <vector>

namespace dg {

/// Throws InputError unless `counts` has one count per direction of `grid`, each in the range
/// it accepts (lowest_count .. max_count).
void check_counts(const GridRule& grid, const std::vector<int>& counts);

/// Where a resize of `grid` to `counts` (one per direction) places the copies of `piece`: per
/// direction, the identity for a head piece, the k-th power of the generator (k = 0 .. count -
/// head and tail units - 1) for a unit piece, the power count - exemplar count for a tail piece;
/// the copies are all combinations (the generators of a grid commute).
std::vector<RigidTransform> piece_placements(const GridRule& grid, const GridPiece& piece, const std::vector<int>& counts);

/// How many triangles (points, for a point-cloud grammar's pieces) a resize of `grid` to
/// `counts` places before welding: each piece's size times its copies (piece_placements), counted
/// without placing them. Throws as resize_grid for counts it refuses.
std::size_t resized_size(const GridRule& grid, const std::vector<GridPiece>& pieces, const std::vector<int>& counts);

/// Assembles the pieces of `grid` for `counts` (one per direction, within the grid's count
/// range), welds seam vertices of different copies closer than grid_weld_tolerance
/// (grammar/grid_seams.h: twice the grid's seam misfit, at least 1e-4 of the voxel size `eps`;
/// vertices of one copy only within 1e-4 eps, see resolve_t_junctions), closes the sliver holes
/// such a weld may leave (three open edges, perimeter up to kSeamHoleFraction eps) and
/// re-triangulates the flat faces the seams split (merge_flat_faces). Counts equal to the
/// grid's own counts reproduce the exemplar. Every triangle keeps its piece triangle's material
/// when all pieces carry materials (the result has none otherwise). Throws InputError when a count is out of range
/// (below a direction's min_units or the grid's range) or the number of counts does not match
/// the grid's dimension.
TriangleMesh resize_grid(const GridRule& grid, const std::vector<GridPiece>& pieces, const std::vector<int>& counts,
                         double eps);

/// Assembles the points of a point-cloud grammar's grid pieces for `counts`, each piece placed
/// as resize_grid places its triangles (normals turned with it when every piece has them; no
/// welding: points have no seams). Throws as resize_grid.
PointCloud resize_grid_points(const GridRule& grid, const std::vector<GridPiece>& pieces, const std::vector<int>& counts);

}  // namespace dg
