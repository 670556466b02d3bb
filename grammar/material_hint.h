#pragma once
// Whether a model's repeats are painted in materials chosen at random (window glass in four
// tints, blinds in two colours): geometry alone may show no repeat (the windows are flat
// patches of the wall), materials matched one by one break it at every tint change, and only
// grouping the interchangeable materials (`--same-material`) gives the grid a person sees.

#include "geometry/prepared_model.h"
#include "grammar/grid_rules.h"
#include "symmetry/symmetry_detection.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace dg {

/// Materials that the translations of a model map onto one another at random, and the grids
/// that matching materials, with them grouped, gives.
struct MaterialHint {
  /// Groups of material names (at least two each), as `--same-material` takes them; empty when
  /// matching every material on its own (`--match-materials`) already gives the grids.
  std::vector<std::vector<std::string>> groups;
  /// Per grid found with the groups: its counts (one per direction).
  std::vector<std::vector<int>> grid_counts;
  /// The options that match the materials so: the analysed ones with match_materials set and
  /// one same_materials entry per group.
  PrepareOptions options;
  /// Whether analyze went on with `options` (its grammar's grids are these) instead of only
  /// naming them.
  bool applied = false;
};

/// Where each material lands under a model's translations: swaps[a][b] is the area of material
/// a's triangles that the first `translations` translation symmetries (in the result's order)
/// map onto a triangle of material b lying in the same plane (within 0.1 eps and 2.5 degrees;
/// triangles whose image lands on no surface do not count). Model units^2.
std::vector<std::vector<double>> material_swaps(const PreparedModel& prepared, const SymmetryResult& symmetries,
                                                std::size_t translations = 8);

/// Groups of interchangeable materials from material_swaps: a material that lands on itself for
/// at least 80 % of its mapped area keeps its own class; the others are joined wherever one
/// lands on the other for at least 10 % of its mapped area. Only groups of two or more are
/// returned, as lists of material indices (ascending, groups by their first index).
std::vector<std::vector<std::uint32_t>> interchangeable_materials(const std::vector<std::vector<double>>& swaps);

/// Whether material_hint searches at all: a mesh with at least two materials, analysed by
/// geometry alone (`options` match no materials), that gave no grid (`grids_found` == 0).
bool material_hint_applies(const PreparedModel& prepared, const PrepareOptions& options, std::size_t grids_found);

/// The first, lighter part of material_hint: the groups and options (grid_counts empty) when
/// the lighter search with them gives a grid, else nothing. For a caller that goes on with the
/// full search itself (analyze, which then analyses the model with those options).
std::optional<MaterialHint> material_grouping(const PreparedModel& prepared, const PrepareOptions& options,
                                              const SymmetryOptions& symmetry_options, std::size_t grids_found,
                                              const ProgressCallback& progress = {});

/// A hint for a mesh with materials analysed by geometry alone (`options` match no materials)
/// that gave no grid: symmetries are detected with materials matched (a lighter search: 4000
/// keypoints, 150 vote sources, 200k pairs, 16 candidates verified), the materials its translations swap are grouped
/// (interchangeable_materials), and grids are sought with materials matched in those groups
/// (or one by one when none formed), first after the lighter search, then, when it gave any,
/// after the full one. The hint holds the groups (none: `--match-materials` alone) and the
/// counts of the full search's grids, when there are any. Nothing
/// otherwise (and nothing for point clouds, models with fewer than two materials, or group
/// names that `--same-material` could not take: with a comma, an asterisk or a quote).
std::optional<MaterialHint> material_hint(const PreparedModel& prepared, const PrepareOptions& options,
                                          const SymmetryOptions& symmetry_options, std::size_t grids_found,
                                          const ProgressCallback& progress = {});

}  // namespace dg
