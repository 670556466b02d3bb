#pragma once
// Resizing several grids of one grammar in one model, one grid after the other.

#include "grammar/grammar_file.h"
#include "grammar/grid_cut.h"

#include <vector>

namespace dg {

/// One grid of a grammar and the counts it is resized to (one per direction).
struct GridResize {
  std::size_t grid = 0;     ///< index in ShapeGrammar::grids
  std::vector<int> counts;  ///< one per direction of that grid
};

/// Resizes the grids named in `resizes` (each at most once) in one copy of the exemplar: the
/// grid that keeps separate parts whole goes first (with its own pieces), then the others in
/// grammar order, each cut again from the result so far along its own planes. Grids given their
/// exemplar's counts are left out; with one resize the result is resize_grid's. Exact when what a
/// resize changes (its unit and tail pieces where the exemplar's counts and the new counts place
/// them) lies in one head or tail piece of every grid resized after it, such as a fence standing
/// above the last step of spiral stairs. Throws InputError when it does not (naming both grids),
/// when two of the grids keep separate parts whole, and for counts resize_grid refuses.
TriangleMesh resize_grids(const ShapeGrammar& grammar, const std::vector<GridResize>& resizes);

/// About how many triangles (points, for a point-cloud grammar) resize_grids places for
/// `resizes`: the exemplar's, plus what each resize adds to its grid's pieces at the exemplar's
/// counts (resized_size), counted without placing anything. Throws as resize_grid for counts it
/// refuses.
std::size_t resized_model_size(const ShapeGrammar& grammar, const std::vector<GridResize>& resizes);

/// resize_grids for a point-cloud grammar (pieces cut again with cut_grid_points).
PointCloud resize_grids_points(const ShapeGrammar& grammar, const std::vector<GridResize>& resizes);

}  // namespace dg
