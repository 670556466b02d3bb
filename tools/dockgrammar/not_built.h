#pragma once
// What analyze found in a model but could not turn into rules, named for that model: the
// "not built" line of the summary, the report's "Not yet built" section and `--json`'s `missing`.

#include "tools/dockgrammar/grammar_report.h"

#include <string>
#include <vector>

namespace dg::cli {

/// One sentence per limit of analyze that this model meets (empty when it meets none): rotation
/// families that repeat short of a full turn (grids of pure rotations are not built),
/// translation families that repeat but gave no grid (other than the one a tolerance hint
/// names) or whose grids span less than half of their repeats, docking sites dropped for a
/// docker that does not fit the other location's seam.
std::vector<std::string> not_built_items(const AnalysisReport& report);

/// The translation families that repeat but gave no grid, as not_built_items names them
/// ("translation F2 (6 repeats of |t| = 54)"); empty when there are none.
std::string translations_without_grid_text(const AnalysisReport& report);

}  // namespace dg::cli
