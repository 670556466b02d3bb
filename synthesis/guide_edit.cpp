#include "synthesis/guide_edit.h"

#include "geometry/errors.h"
#include "synthesis/mass_spring.h"

#include <cmath>
#include <numbers>
#include <string>

namespace dg {

namespace {

// Applies the affine map p -> rotation * p + shift to a guide's polygon and seeds.
void move_guide(Guide& guide, double angle_deg, double factor, const Vec2& pivot, const Vec2& shift) {
  const double radians = angle_deg * std::numbers::pi / 180.0;
  const double c = std::cos(radians) * factor, s = std::sin(radians) * factor;
  auto map = [&](const Vec2& p) {
    const Vec2 q = p - pivot;
    return Vec2(pivot.x() + c * q.x() - s * q.y() + shift.x(), pivot.y() + s * q.x() + c * q.y() + shift.y());
  };
  for (Vec2& v : guide.polygon) v = map(v);
  for (GuideSeed& seed : guide.seeds) {
    seed.position = map(seed.position);
    seed.heading_deg += angle_deg;
  }
}

Vec2 centroid(const Guide& guide) {
  Vec2 sum = Vec2::Zero();
  for (const Vec2& v : guide.polygon) sum += v;
  return sum / static_cast<double>(guide.polygon.size());
}

void check_index(std::size_t index, std::size_t size, const std::string& what) {
  if (index >= size) throw InputError("edit: " + what + " " + std::to_string(index) + " does not exist");
}

}  // namespace

std::vector<std::size_t> apply_guide_edit(GrowthScene& scene, const GuideEdit& edit) {
  check_index(edit.guide, scene.guides.size(), "guide");
  Guide& guide = scene.guides[edit.guide];
  switch (edit.kind) {
    case GuideEdit::Kind::Translate:
      move_guide(guide, 0, 1, Vec2::Zero(), edit.offset);
      break;
    case GuideEdit::Kind::Rotate:
      move_guide(guide, edit.angle_deg, 1, centroid(guide), Vec2::Zero());
      break;
    case GuideEdit::Kind::Scale:
      if (!(edit.factor > 0)) throw InputError("edit: the scale factor must be positive");
      move_guide(guide, 0, edit.factor, centroid(guide), Vec2::Zero());
      break;
    case GuideEdit::Kind::MoveVertex:
      check_index(edit.vertex, guide.polygon.size(), "vertex");
      return drag_guide_vertex(scene, edit.guide, edit.vertex, edit.offset);
    case GuideEdit::Kind::Snap: {
      check_index(edit.target, scene.guides.size(), "guide");
      if (edit.target == edit.guide) throw InputError("edit: a guide cannot snap onto itself");
      check_index(edit.edge, guide.polygon.size(), "edge");
      const Guide& target = scene.guides[edit.target];
      check_index(edit.target_edge, target.polygon.size(), "edge");
      const std::size_t n = guide.polygon.size(), m = target.polygon.size();
      const Vec2 a = guide.polygon[edit.edge], b = guide.polygon[(edit.edge + 1) % n];
      const Vec2 c = target.polygon[edit.target_edge], d = target.polygon[(edit.target_edge + 1) % m];
      const Vec2 from = b - a, to = c - d;
      const double angle = (std::atan2(to.y(), to.x()) - std::atan2(from.y(), from.x())) * 180.0 / std::numbers::pi;
      move_guide(guide, angle, 1, 0.5 * (a + b), 0.5 * (c + d) - 0.5 * (a + b));
      guide.polygon[edit.edge] = d;
      guide.polygon[(edit.edge + 1) % n] = c;
      break;
    }
  }
  return {edit.guide};
}

}  // namespace dg
