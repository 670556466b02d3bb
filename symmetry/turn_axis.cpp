#include "symmetry/turn_axis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace dg {

std::optional<TurnAxis> coordinate_turn_axis(const SymmetryResult& symmetries, double min_fraction) {
  const double degree = std::numbers::pi / 180.0;
  const double max_angle = 120.0 * degree + 1.0 * degree;  // a third of a turn, with the detector's angle noise
  const double min_axis_cos = std::cos(1.0 * degree);
  std::optional<TurnAxis> best;
  std::array<bool, 3> axis_turns{false, false, false};
  for (std::size_t f = 0; f < symmetries.families.size(); ++f) {
    const SymmetryFamily& family = symmetries.families[f];
    if (family.kind == "translation" || family.generator.angle() > max_angle) continue;
    const Vec3 axis = family.generator.axis();
    int coordinate = 0;
    axis.cwiseAbs().maxCoeff(&coordinate);
    if (std::abs(axis[coordinate]) < min_axis_cos) continue;
    double fraction = 0.0;
    for (std::size_t m : family.members) fraction = std::max(fraction, symmetries.symmetries[m].symmetric_fraction);
    if (fraction < min_fraction) continue;
    axis_turns[static_cast<std::size_t>(coordinate)] = true;
    if (!best || fraction > best->fraction) best = TurnAxis{coordinate, f, fraction};
  }
  // Turns about two axes (a stack of cubes, each turning about all three) say nothing about up.
  if (std::count(axis_turns.begin(), axis_turns.end(), true) > 1) return std::nullopt;
  return best;
}

}  // namespace dg
