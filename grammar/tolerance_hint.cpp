#include "grammar/tolerance_hint.h"

#include <algorithm>

namespace dg {

std::optional<ToleranceHint> tolerance_hint(const PreparedModel& prepared, const SymmetryResult& symmetries,
                                            const std::vector<GridWithPieces>& grids) {
  if (prepared.model.is_point_cloud() || symmetries.region.offset_tolerance_eps != RegionOptions{}.offset_tolerance_eps)
    return std::nullopt;
  ToleranceHint hint;
  for (const GridWithPieces& grid : grids)
    for (const GridDirection& d : grid.rule.directions) hint.grid_units = std::max(hint.grid_units, d.count);
  const std::vector<SymmetryFamily>& families = symmetries.families;
  std::optional<std::size_t> most;
  for (std::size_t f = 0; f < families.size(); ++f)
    if (families[f].kind == "translation" && (!most || families[f].count > families[*most].count)) most = f;
  if (!most || families[*most].count < static_cast<std::size_t>(2 * hint.grid_units + 2)) return std::nullopt;
  hint.family = *most;
  hint.repeats = families[*most].count;

  const DetectedSymmetry* best = nullptr;
  for (std::size_t member : families[*most].members)
    if (!best || symmetries.symmetries[member].r_symmetric_area > best->r_symmetric_area) best = &symmetries.symmetries[member];
  const VoxelSurface& surface = prepared.surface;
  const double total = surface.total_area();
  if (!best || total <= 0.0) return std::nullopt;
  hint.r_symmetric_now =
      tested_symmetric_region(CellMatcher(surface, nullptr, symmetries.region), surface, best->transform).r_symmetric_area / total;
  for (double tolerance : kSuggestedTolerancesEps) {
    RegionOptions wider = symmetries.region;
    wider.offset_tolerance_eps = tolerance;
    hint.tolerance_eps = tolerance;
    hint.r_symmetric_wider =
        tested_symmetric_region(CellMatcher(surface, nullptr, wider), surface, best->transform).r_symmetric_area / total;
    if (hint.r_symmetric_wider >= hint.r_symmetric_now + 0.05) return hint;
  }
  return std::nullopt;
}

}  // namespace dg
