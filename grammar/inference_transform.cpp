#include "grammar/inference_transform.h"

#include <cmath>
#include <numbers>

namespace dg {

namespace {
constexpr double kDegree = std::numbers::pi / 180;
}

double wrap_degrees(double angle_deg) {
  double a = std::fmod(angle_deg, 360.0);
  if (a <= -180) a += 360;
  if (a > 180) a -= 360;
  return a;
}

int transform_command_count(const TurtleTransform& start, const TurtleTransform& slope) {
  int count = 0;
  if (slope[0] != 0 || std::abs(start[0]) >= trivial_turn_deg) ++count;
  if (slope[1] != 0 || std::abs(start[1]) >= trivial_move) ++count;
  if (slope[2] != 0 || std::abs(start[2] - 1) >= trivial_scale) ++count;
  if (slope[3] != 0 || std::abs(start[3]) >= trivial_turn_deg) ++count;
  return count;
}

TurtleTransform relative_transform(const InstanceFrame& from, const InstanceFrame& to) {
  const Vec2 v = to.position - from.position;
  const double distance = v.norm();
  const double direction = distance > 1e-12 * std::max(1.0, from.position.norm()) ? std::atan2(v.y(), v.x()) / kDegree : from.angle_deg;
  const double alpha = wrap_degrees(direction - from.angle_deg);
  const double beta = wrap_degrees(to.angle_deg - from.angle_deg - alpha);
  return {alpha, distance / from.scale, to.scale / from.scale, beta};
}

InstanceFrame apply_transform(const InstanceFrame& from, const TurtleTransform& t) {
  const double heading = (from.angle_deg + t[0]) * kDegree;
  InstanceFrame out;
  out.position = from.position + from.scale * t[1] * Vec2(std::cos(heading), std::sin(heading));
  out.scale = from.scale * t[2];
  out.angle_deg = wrap_degrees(from.angle_deg + t[0] + t[3]);
  return out;
}

}  // namespace dg
