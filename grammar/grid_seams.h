#pragma once
// Where a resize joins the pieces of a grid, how closely their seams meet. Copies of the repeated
// unit meet the unit's own bottom moved by the generator, and the last copy meets the tail (or,
// with no copy, the head meets it) moved by a power of the generator. Exact repeats meet up to
// float rounding; repeats matched within a wider tolerance (`--tolerance`) meet only that closely,
// and resize welds their seams within twice the distance measured here.

#include "grammar/grid_cut.h"
#include "grammar/grid_rules.h"
#include "grammar/seam_curve.h"

#include <vector>

namespace dg {

/// The largest distance (model units) between the seams that a resize of `grid` joins: for each
/// direction, the open edges of the pieces lying on the planes where unit meets unit, unit meets
/// tail and (when the count may drop to the units head and tail keep) head meets tail, compared
/// as seam curves (seam_misfit, grammar/seam_curve.h) after moving one side into place. A joint
/// where some point of either seam has no partner within eps is left out (no weld distance worth
/// using closes it). 0 for point-cloud pieces.
double grid_seam_misfit(const GridRule& grid, const std::vector<GridPiece>& pieces, double eps);

/// Distance (model units) within which resize welds the seam vertices of `grid`'s pieces: twice
/// its seam misfit, at least kSeamWeldFloorFraction eps.
double grid_weld_tolerance(const GridRule& grid, double eps);

}  // namespace dg
