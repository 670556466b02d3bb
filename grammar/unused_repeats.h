#pragma once
// Repeats that a model shows but that its grids do not use: what analyze found and could not
// turn into grid rules, so that the report can name them for this model.

#include "grammar/grid_rules.h"
#include "symmetry/symmetry_detection.h"

#include <cstddef>
#include <vector>

namespace dg {

/// A translation family that grids along it use for fewer than half of its repeats.
struct ShortRun {
  std::size_t family = 0;  ///< index into SymmetryResult::families
  double spanned = 0.0;    ///< repeats of its generator that those grids span (count x pitch / |generator|, summed)
};

/// Symmetry families (indices into SymmetryResult::families) that repeat, at least `min_repeats`
/// times (SymmetryFamily::count), but that no grid uses, or uses for only part of its repeats.
struct UnusedRepeats {
  /// Translations that lie (within 1 degree) in the span of no grid's direction translations.
  std::vector<std::size_t> translations;
  /// Rotations (no slide along the axis) whose repeats do not close a full turn: grids of pure
  /// rotations are not built. A full turn (n - 1 repeats of 360/n degrees) could take no further
  /// unit without changing the angle, so it is no grid and is not listed.
  std::vector<std::size_t> partial_turns;
  /// Translations whose repeats the grid directions along them (translations parallel to the
  /// generator within 1 degree, not screws) span less than half of: planes elsewhere along them
  /// would cut connected geometry that does not repeat with the units (a radiator's wall brackets
  /// across its fins), so the grids cover one stretch.
  std::vector<ShortRun> short_runs;
};

/// The unused repeats of `symmetries` given the grids built from them.
UnusedRepeats unused_repeats(const SymmetryResult& symmetries, const std::vector<GridRule>& grids, int min_repeats);

}  // namespace dg
