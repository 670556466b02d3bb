#pragma once
// Resizing a grid: head pieces once, the repeated unit count times, tail pieces shifted to
// the end, in every direction of the grid (corners once, borders along one direction, the
// interior along all), welded into one mesh.

#include "grammar/grid_rules.h"

#include <vector>

namespace dg {

/// Assembles the pieces of `grid` for `counts` (one per direction, within the grid's count
/// range) and welds vertices closer than `weld_tolerance` (model units). Counts equal to the
/// grid's own counts reproduce the exemplar. Throws InputError when a count is out of range
/// or the number of counts does not match the grid's dimension.
TriangleMesh resize_grid(const GridRule& grid, const std::vector<GridPiece>& pieces, const std::vector<int>& counts,
                         double weld_tolerance);

}  // namespace dg
