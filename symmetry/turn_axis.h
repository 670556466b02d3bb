#pragma once
// A model's up axis read off its symmetries: round tables, chandeliers, towers and spiral stairs
// turn about their vertical, whatever axis the file's convention calls up.

#include "symmetry/symmetry_detection.h"

#include <cstddef>
#include <optional>

namespace dg {

/// The coordinate axis a model's dominant turn is about.
struct TurnAxis {
  int axis = 1;             ///< 0 = x, 1 = y, 2 = z
  std::size_t family = 0;   ///< index into SymmetryResult::families
  double fraction = 0.0;    ///< of the model's surface that the family's motions map onto itself (largest member)
};

/// Turns of a family count from this share of the model's surface (symmetric area, largest member).
inline constexpr double kTurnAxisShare = 0.5;

/// The rotation or screw family that turns by at most 120 degrees (three or more steps to a full
/// turn: a 180-degree flip says nothing about up) about an axis within 1 degree of a coordinate
/// axis, whose motions map at least `min_fraction` of the model's surface onto itself, the
/// largest such; nothing when there is none, or when such turns are about two or more axes (a
/// stack of cubes turns about all three).
std::optional<TurnAxis> coordinate_turn_axis(const SymmetryResult& symmetries, double min_fraction = kTurnAxisShare);

}  // namespace dg
