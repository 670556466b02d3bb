#pragma once
// Whether matching cells within a wider position tolerance would let a translation repeat over
// more of the surface: repeats placed or modelled a little unevenly (hand-made railings) break
// the exact test, and with it the grid planes between them.

#include "geometry/prepared_model.h"
#include "grammar/grammar_file.h"
#include "symmetry/symmetry_detection.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace dg {

/// The tolerances (eps) a hint tries, smallest first; it suggests the first that is enough.
inline constexpr double kSuggestedTolerancesEps[] = {0.25, 0.5};

/// A translation family whose r-symmetric area grows at the suggested tolerance.
struct ToleranceHint {
  std::size_t family = 0;   ///< index into SymmetryResult::families
  std::size_t repeats = 0;  ///< its repeat count
  int grid_units = 0;       ///< most units of any grid direction (0: no grid)
  double tolerance_eps = 0.0;  ///< the suggested tolerance, one of kSuggestedTolerancesEps
  /// r-symmetric area of the family's member that repeats over the most surface, every cell
  /// tested, as fractions of the surface: at the tolerance used, and at the suggested one.
  double r_symmetric_now = 0.0, r_symmetric_wider = 0.0;
};

/// A hint for a mesh whose symmetries were matched at the default tolerance, when the
/// translation family with the most repeats repeats at least 2 x grid_units + 2 times and its
/// best member's r-symmetric area grows by at least 5 % of the surface at one of
/// kSuggestedTolerancesEps (the smallest such is suggested); nothing otherwise.
std::optional<ToleranceHint> tolerance_hint(const PreparedModel& prepared, const SymmetryResult& symmetries,
                                            const std::vector<GridWithPieces>& grids);

}  // namespace dg
