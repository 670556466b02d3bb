#include "grammar/material_analysis.h"

#include "geometry/stopwatch.h"

#include <fmt/core.h>

namespace dg {

std::optional<GroupedMaterialAnalysis> analyze_with_materials_grouped(const std::filesystem::path& model_path,
                                                                      const PreparedModel& prepared,
                                                                      const PrepareOptions& options,
                                                                      const SymmetryOptions& symmetry_options,
                                                                      std::size_t grids_found,
                                                                      const ProgressCallback& progress) {
  Stopwatch stopwatch;
  std::optional<MaterialHint> hint = material_grouping(prepared, options, symmetry_options, grids_found, progress);
  if (!hint) return std::nullopt;
  const double grouping_seconds = stopwatch.lap();
  ProgressCallback grouped_progress;
  if (progress)
    grouped_progress = [&progress](std::string_view stage, double fraction) {
      return progress(fmt::format("materials grouped: {}", stage), fraction);
    };
  PreparedModel grouped = prepare_model(model_path, hint->options, grouped_progress);
  SymmetryResult symmetries = detect_symmetries(grouped, symmetry_options, grouped_progress);
  stopwatch.lap();  // the grouped model's stages time themselves
  std::vector<GridRule> grids = find_grids(grouped, symmetries, {}, grouped_progress);
  if (grids.empty()) return std::nullopt;
  hint->applied = true;
  for (const GridRule& grid : grids) hint->grid_counts.push_back(exemplar_counts(grid));
  return GroupedMaterialAnalysis{.hint = std::move(*hint), .prepared = std::move(grouped), .symmetries = std::move(symmetries),
                                 .grids = std::move(grids), .grouping_seconds = grouping_seconds,
                                 .grid_seconds = stopwatch.lap()};
}

}  // namespace dg
