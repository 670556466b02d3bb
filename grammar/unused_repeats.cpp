#include "grammar/unused_repeats.h"

#include <Eigen/QR>

#include <cmath>
#include <numbers>

namespace dg {
namespace {

// Sine of the angle (1 degree) within which a translation counts as lying along a grid's.
const double kAlongSine = std::sin(std::numbers::pi / 180.0);

// Whether translation `t` lies (within 1 degree) in the span of the direction translations of
// some grid of `grids` (a 2-grid's diagonal steps included).
bool in_a_grid(const Vec3& t, const std::vector<GridRule>& grids) {
  if (t.norm() <= 0.0) return false;
  for (const GridRule& grid : grids) {
    Eigen::MatrixXd span(3, static_cast<Eigen::Index>(grid.directions.size()));
    for (std::size_t i = 0; i < grid.directions.size(); ++i) span.col(static_cast<Eigen::Index>(i)) = grid.directions[i].translation;
    const Vec3 in_span = span * span.colPivHouseholderQr().solve(t);
    if ((t - in_span).norm() <= kAlongSine * t.norm()) return true;
  }
  return false;
}

// Repeats of translation `t` that the directions of `grids` along it span: each pure
// translation parallel to t (within 1 degree) spans its count times its pitch over |t|.
double spanned_repeats(const Vec3& t, const std::vector<GridRule>& grids) {
  double spanned = 0.0;
  for (const GridRule& grid : grids)
    for (const GridDirection& d : grid.directions) {
      const bool parallel = d.translation.cross(t).norm() <= kAlongSine * d.pitch * t.norm();
      if (d.motion.rotation.isIdentity(1e-9) && d.pitch > 0.0 && parallel) spanned += static_cast<double>(d.count) * d.pitch / t.norm();
    }
  return spanned;
}

}  // namespace

UnusedRepeats unused_repeats(const SymmetryResult& symmetries, const std::vector<GridRule>& grids, int min_repeats) {
  UnusedRepeats unused;
  for (std::size_t f = 0; f < symmetries.families.size(); ++f) {
    const SymmetryFamily& family = symmetries.families[f];
    if (static_cast<int>(family.count) < min_repeats) continue;
    const bool full_turn = family.order > 0 && static_cast<int>(family.count) >= family.order - 1;
    if (family.kind == "rotation" && !full_turn) unused.partial_turns.push_back(f);
    if (family.kind != "translation") continue;
    const Vec3& t = family.generator.translation;
    if (!in_a_grid(t, grids)) {
      unused.translations.push_back(f);
    } else if (const double spanned = spanned_repeats(t, grids); spanned > 0.0 && short_run(spanned, family.count)) {
      unused.short_runs.push_back({f, spanned});
    }
  }
  return unused;
}

}  // namespace dg
