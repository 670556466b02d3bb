#include "synthesis/segment2d.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dg {

double closest_parameter(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  if (length2 == 0) return 0;
  return std::clamp((p - a).dot(ab) / length2, 0.0, 1.0);
}

double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  return (a + closest_parameter(p, a, b) * (b - a) - p).norm();
}

std::optional<SegmentCrossing> cross_segments(const Vec2& p, const Vec2& q, const Vec2& a, const Vec2& b) {
  const Vec2 r = q - p, e = b - a;
  const double denominator = cross2(r, e);
  if (denominator == 0) return std::nullopt;
  const Vec2 ap = a - p;
  const double s = cross2(ap, e) / denominator;
  const double u = cross2(ap, r) / denominator;
  // A tolerance of 1e-9 keeps crossings exactly through an end point (common in regular
  // layouts) from slipping between two segments by rounding.
  constexpr double slack = 1e-9;
  if (s < -slack || s > 1 + slack || u < -slack || u > 1 + slack) return std::nullopt;
  return SegmentCrossing{std::clamp(s, 0.0, 1.0), std::clamp(u, 0.0, 1.0)};
}

bool point_in_polygon(const Vec2& p, const std::vector<Vec2>& polygon) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
      inside = !inside;
  }
  return inside;
}

bool polygon_self_intersects(const std::vector<Vec2>& polygon) {
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i)
    if (polygon[i] == polygon[(i + 1) % n]) return true;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % n];
    for (std::size_t j = i + 1; j < n; ++j) {
      const Vec2& c = polygon[j];
      const Vec2& d = polygon[(j + 1) % n];
      const bool neighbours = j == i + 1 || (i == 0 && j == n - 1);
      if (neighbours) {
        // Neighbours share one vertex; they fold back when collinear and pointing back.
        const Vec2 shared = j == i + 1 ? b : a;
        const Vec2 u = (j == i + 1 ? a : b) - shared, v = (j == i + 1 ? d : c) - shared;
        if (cross2(u, v) == 0 && u.dot(v) > 0) return true;
        continue;
      }
      if (cross_segments(a, b, c, d)) return true;
    }
  }
  return false;
}

double polygon_signed_area(const std::vector<Vec2>& polygon) {
  double area = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) area += cross2(polygon[i], polygon[(i + 1) % polygon.size()]);
  return area / 2;
}

double turn_toward(double heading_deg, const Vec2& to) {
  const Vec2 h = heading_vector(heading_deg);
  return std::atan2(cross2(h, to), h.dot(to)) * 180.0 / std::numbers::pi;
}

Vec2 heading_vector(double heading_deg) {
  const double radians = heading_deg * std::numbers::pi / 180.0;
  return Vec2(std::cos(radians), std::sin(radians));
}

}  // namespace dg
