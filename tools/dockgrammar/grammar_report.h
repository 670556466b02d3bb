#pragma once
// What `analyze` tells the user: text summary, JSON summary, Markdown report and pictures.

#include "geometry/prepared_model.h"
#include "grammar/context_free.h"
#include "grammar/docking_sites.h"
#include "grammar/grammar_file.h"
#include "grammar/material_hint.h"
#include "grammar/tolerance_hint.h"
#include "symmetry/symmetry_detection.h"
#include "tools/dockgrammar/up_axis.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace dg::cli {

struct AnalysisReport {
  const PreparedModel& prepared;
  const SymmetryResult& symmetries;
  const ShapeGrammar& grammar;
  const DockingSiteResult& docking;
  ContextFreeStats context_free;             ///< what became of the docking sites
  std::vector<StageTiming> grammar_timings;  ///< grid rules, docking sites, context-free rules
  std::filesystem::path grammar_path;
  std::filesystem::path report_path;
  std::vector<std::filesystem::path> pictures;  ///< PNG files written by write_analysis_pictures
  std::optional<ToleranceHint> tolerance_hint;  ///< a wider --tolerance that would help (grammar/tolerance_hint.h)
  std::optional<MaterialHint> material_hint;    ///< material matching that gives grids (grammar/material_hint.h), applied or not
  UpAxisChoice up;                              ///< grammar.up_axis and what it was read from
};

/// Short readable summary for stdout.
std::string analysis_text(const AnalysisReport& report);

/// {r, eps, up (the stored up axis "x", "y" or "z", or null: pictures guess), materials (names), match_materials, material_groups, material_hint (null, or
/// {same_material: [[names]] (empty: --match-materials alone), grid_counts, applied: analyze went
/// on with them}), symmetries, families,
/// docking_sites, dockers, operations, nonterminals, productions, grids: [{name, dims, counts,
/// transforms, count_range, further_run_of (null, or {grid, direction} whose motion it shares),
/// groups_units_of (null, or {grid, direction, factor} whose units it groups by factor), pieces}], grammar_file, timings_s, missing (what this model shows that
/// analyze could not turn into rules, one sentence each, see not_built_items)}.
nlohmann::json analysis_json(const AnalysisReport& report);

/// report.report_path (NAME.report.md): cleaning, symmetries, grids with counts and pieces,
/// docking sites and context-free rules, pictures, timings, what is missing.
void write_analysis_report(const AnalysisReport& report);

/// NAME.<grid>.png and NAME.<grid>.ply: the model coloured by grid piece class (corners, borders,
/// interior; repeated units in alternating shades), for every grid; NAME.rules.png/.ply when
/// there are context-free rules; NAME.sites.png/.ply when there are docking sites. The pictures
/// look at the model with the grammar's up axis (guessed when it has none).
/// Returns the PNG files it wrote.
std::vector<std::filesystem::path> write_analysis_pictures(const std::filesystem::path& folder, const std::string& stem,
                                                           const AnalysisReport& report);

}  // namespace dg::cli
