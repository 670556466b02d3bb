#pragma once
// Analysing a model again with its interchangeable materials grouped, when geometry alone gave
// no grid (grammar/material_hint.h): `analyze` goes on with that analysis instead of only naming
// its options.

#include "geometry/prepared_model.h"
#include "grammar/grid_rules.h"
#include "grammar/material_hint.h"
#include "symmetry/symmetry_detection.h"

#include <filesystem>
#include <optional>
#include <vector>

namespace dg {

/// The model analysed with the materials of material_grouping's groups matched.
struct GroupedMaterialAnalysis {
  MaterialHint hint;            ///< applied, with the counts of `grids`
  PreparedModel prepared;       ///< the model file prepared again with hint.options
  SymmetryResult symmetries;    ///< of `prepared`, with the caller's search options
  std::vector<GridRule> grids;  ///< not empty
  double grouping_seconds = 0.0;  ///< the search for the groups (material_grouping)
  double grid_seconds = 0.0;      ///< find_grids on `prepared`
};

/// For `prepared`, loaded from `model_path` with `options` and given no grid by geometry alone
/// (material_hint_applies with `grids_found`): prepares the file again with the materials of
/// material_grouping's groups matched, detects its symmetries with `symmetry_options` and seeks
/// its grids. The analysis when that gives a grid; nothing when material_grouping finds no
/// groups that give one, or the full search gives none. The file is read again (not the
/// cleaned model re-prepared) so the new model's cleaning and origin are those of the file.
/// The second analysis reports progress under stage names prefixed "materials grouped: ".
std::optional<GroupedMaterialAnalysis> analyze_with_materials_grouped(const std::filesystem::path& model_path,
                                                                      const PreparedModel& prepared,
                                                                      const PrepareOptions& options,
                                                                      const SymmetryOptions& symmetry_options,
                                                                      std::size_t grids_found,
                                                                      const ProgressCallback& progress = {});

}  // namespace dg
