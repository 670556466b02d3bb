#pragma once
// Instance frames and the pairwise turtle transform (alpha, d, s, beta) of Št'ava et al. 2010
// §4.2: the turtle at instance A reaches instance B by +(alpha) f(d) *(s) +(beta).

#include "geometry/types.h"

#include <array>

namespace dg {

/// Where an instance sits in the drawing: y-up drawing units, angle in degrees counter-clockwise
/// (0 = +x), scale relative to its terminal's representative (which has scale 1).
struct InstanceFrame {
  Vec2 position = Vec2::Zero();
  double angle_deg = 0;
  double scale = 1;
};

/// The relative transform as the turtle commands +(alpha) f(d) *(s) +(beta), read in A's frame:
/// alpha and beta in degrees in (-180, 180], d in A's local units (world distance / A's scale),
/// s = scale of B / scale of A. Stored as {alpha, d, s, beta}.
using TurtleTransform = std::array<double, 4>;

/// Below these the turtle commands of a transform are trivial and left out (§5.7): turns in
/// degrees, moves in drawing units, scale factors as |s - 1|.
inline constexpr double trivial_turn_deg = 0.005;
inline constexpr double trivial_move = 5e-4;
inline constexpr double trivial_scale = 1e-3;

/// Number of turtle commands +(alpha) f(d) *(s) +(beta) that are not trivial for the transform
/// start + slope m (a coordinate with a slope always counts).
int transform_command_count(const TurtleTransform& start, const TurtleTransform& slope);

/// Angle in degrees wrapped to (-180, 180].
double wrap_degrees(double angle_deg);

/// The transform that takes the turtle from `from` to `to` (alpha = 0 when they coincide).
TurtleTransform relative_transform(const InstanceFrame& from, const InstanceFrame& to);

/// The frame the turtle reaches from `from` by executing `transform`.
InstanceFrame apply_transform(const InstanceFrame& from, const TurtleTransform& transform);

}  // namespace dg
