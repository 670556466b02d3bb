#include "geometry/box_overlap.h"

#include <algorithm>
#include <cmath>

namespace dg {
namespace {

// Projects the triangle (relative to the box centre) and the box onto `axis` and reports
// whether the intervals are disjoint. A zero axis never separates.
bool separated_on(const Vec3& axis, const Vec3& v0, const Vec3& v1, const Vec3& v2, const Vec3& half, double margin) {
  const double p0 = axis.dot(v0), p1 = axis.dot(v1), p2 = axis.dot(v2);
  const double radius = (half.x() + margin) * std::abs(axis.x()) + (half.y() + margin) * std::abs(axis.y()) +
                        (half.z() + margin) * std::abs(axis.z());
  const double lo = std::min({p0, p1, p2}), hi = std::max({p0, p1, p2});
  return lo > radius || hi < -radius;
}

}  // namespace

bool triangle_box_overlap(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& lo, const Vec3& hi) {
  const Vec3 centre = 0.5 * (lo + hi);
  const Vec3 half = 0.5 * (hi - lo);
  const Vec3 v0 = a - centre, v1 = b - centre, v2 = c - centre;
  // Rounding in the box corners (i * eps) and in the differences above can move a face lying
  // exactly on a box face by an ulp; a margin of 1e-10 of the coordinates' size keeps it touching.
  const double margin = 1e-10 * (half.maxCoeff() + centre.cwiseAbs().maxCoeff());
  // Box face normals: compare the triangle's bounding box with the box.
  for (int axis = 0; axis < 3; ++axis) {
    const double tmin = std::min({v0[axis], v1[axis], v2[axis]});
    const double tmax = std::max({v0[axis], v1[axis], v2[axis]});
    if (tmin > half[axis] + margin || tmax < -half[axis] - margin) return false;
  }
  const Vec3 edges[3] = {v1 - v0, v2 - v1, v0 - v2};
  // Triangle normal.
  if (separated_on(edges[0].cross(edges[1]), v0, v1, v2, half, margin)) return false;
  // Edge x box-axis cross products.
  for (const Vec3& e : edges) {
    if (separated_on(Vec3(0.0, -e.z(), e.y()), v0, v1, v2, half, margin)) return false;
    if (separated_on(Vec3(e.z(), 0.0, -e.x()), v0, v1, v2, half, margin)) return false;
    if (separated_on(Vec3(-e.y(), e.x(), 0.0), v0, v1, v2, half, margin)) return false;
  }
  return true;
}

}  // namespace dg
