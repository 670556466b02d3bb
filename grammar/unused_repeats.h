#pragma once
// Repeats that a model shows but that its grids do not use: what analyze found and could not
// turn into grid rules, so that the report can name them for this model.

#include "grammar/grid_rules.h"
#include "symmetry/symmetry_detection.h"

#include <cstddef>
#include <vector>

namespace dg {

/// Symmetry families (indices into SymmetryResult::families) that repeat, at least `min_repeats`
/// times (SymmetryFamily::count), but that no grid uses.
struct UnusedRepeats {
  /// Translations that lie (within 1 degree) in the span of no grid's direction translations.
  std::vector<std::size_t> translations;
  /// Rotations (no slide along the axis) whose repeats do not close a full turn: grids of pure
  /// rotations are not built. A full turn (n - 1 repeats of 360/n degrees) could take no further
  /// unit without changing the angle, so it is no grid and is not listed.
  std::vector<std::size_t> partial_turns;
};

/// The unused repeats of `symmetries` given the grids built from them.
UnusedRepeats unused_repeats(const SymmetryResult& symmetries, const std::vector<GridRule>& grids, int min_repeats);

}  // namespace dg
