#include "tools/dockgrammar/not_built.h"

#include "grammar/seam_curve.h"
#include "grammar/unused_repeats.h"

#include <fmt/format.h>

#include <algorithm>
#include <numbers>

namespace dg::cli {
namespace {

// At most this many families are named in one sentence; the rest are counted.
constexpr std::size_t kNamedFamilies = 3;

// "F3 (13 repeats of |t| = 16.8)" or "F6 (4 repeats of 18 deg)".
std::string family_text(const SymmetryResult& symmetries, std::size_t f) {
  const SymmetryFamily& family = symmetries.families[f];
  if (family.kind == "rotation")
    return fmt::format("F{} ({} repeats of {:.3g} deg)", f + 1, family.count, family.generator.angle() * 180.0 / std::numbers::pi);
  return fmt::format("F{} ({} repeats of |t| = {:.3g})", f + 1, family.count, family.generator.translation.norm());
}

// "rotation F1 (...)" / "rotations F1 (...), F4 (...) and 2 more".
std::string families_text(const SymmetryResult& symmetries, const std::vector<std::size_t>& families, const char* kind) {
  std::string text = fmt::format("{}{}", kind, families.size() == 1 ? "" : "s");
  const std::size_t named = std::min(families.size(), kNamedFamilies);
  for (std::size_t i = 0; i < named; ++i)
    text += (i == 0 ? " " : (i + 1 == named && named == families.size() ? " and " : ", ")) + family_text(symmetries, families[i]);
  if (families.size() > named) text += fmt::format(" and {} more", families.size() - named);
  return text;
}

// The repeating families no grid uses, less the one a tolerance hint names with a remedy.
UnusedRepeats unused_repeats_of(const AnalysisReport& report) {
  std::vector<GridRule> grids;
  for (const GridWithPieces& grid : report.grammar.grids) grids.push_back(grid.rule);
  UnusedRepeats unused = unused_repeats(report.symmetries, grids, GridOptions{}.min_repeats);
  if (report.tolerance_hint) std::erase(unused.translations, report.tolerance_hint->family);
  return unused;
}

}  // namespace

std::string translations_without_grid_text(const AnalysisReport& report) {
  const UnusedRepeats unused = unused_repeats_of(report);
  return unused.translations.empty() ? "" : families_text(report.symmetries, unused.translations, "translation");
}

std::vector<std::string> not_built_items(const AnalysisReport& report) {
  const UnusedRepeats unused = unused_repeats_of(report);
  std::vector<std::string> items;
  if (!unused.partial_turns.empty())
    items.push_back(fmt::format("{} give{} no grid: grids of pure rotations (no slide along the axis) are not built",
                                families_text(report.symmetries, unused.partial_turns, "rotation"),
                                unused.partial_turns.size() == 1 ? "s" : ""));
  if (!unused.translations.empty())
    items.push_back(fmt::format("{} give{} no grid: grid planes cross the whole model but for separate parts kept whole, "
                                "and no such planes cut it into slabs that repeat (geometry that does not repeat with "
                                "the units lies across them, or the slabs are an extrusion that only slides along itself)",
                                families_text(report.symmetries, unused.translations, "translation"),
                                unused.translations.size() == 1 ? "s" : ""));
  for (const ShortRun& run : unused.short_runs)
    items.push_back(fmt::format("translation {}: the grids along it span only {:.3g} of its repeats; elsewhere along it, "
                                "planes at its pitch cut no slabs that repeat the unit (connected geometry that does not "
                                "repeat with the units lies across them, such as a radiator's wall brackets across its fins, "
                                "or the units there differ from the repeated one by more than --tolerance)",
                                family_text(report.symmetries, run.family), run.spanned));
  const ContextFreeStats& stats = report.context_free;
  const bool one = stats.sites_without_fit == 1;
  if (stats.sites_without_fit > 0 && report.prepared.model.is_point_cloud())
    items.push_back(fmt::format("{} docking site{} whose docker's points next to the seam differ from those at the other "
                                "location give{} no context-free production",
                                stats.sites_without_fit, one ? "" : "s", one ? "s" : ""));
  else if (stats.sites_without_fit > 0)
    items.push_back(fmt::format("{} docking site{} give{} no context-free production: the docker cut at one location "
                                "does not fit the hole at the other (their seams lie more than {:g} eps apart, a little "
                                "where repeats were modelled unevenly, wholly where the geometry around the two "
                                "locations differs)",
                                stats.sites_without_fit, one ? "" : "s", one ? "s" : "", kSeamFitFraction));
  if (stats.sites_stray_seam > 0)
    items.push_back(fmt::format("{} docking site{} give{} no context-free production: part of the site's image borders "
                                "nothing the operation replaces, so the seam at the second location is not the first's "
                                "moved",
                                stats.sites_stray_seam, stats.sites_stray_seam == 1 ? "" : "s",
                                stats.sites_stray_seam == 1 ? "s" : ""));
  return items;
}

}  // namespace dg::cli
