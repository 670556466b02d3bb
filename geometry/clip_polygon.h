#pragma once
// Internal: a small convex polygon clipped against axis-aligned slabs (voxelization, cutting).

#include "geometry/types.h"

#include <array>
#include <utility>

namespace dg {

/// Polygon for clipping a triangle against axis slabs (a triangle clipped by six planes has at
/// most nine corners).
struct ClipPolygon {
  std::array<Vec3, 10> points;
  int size = 0;

  /// The triangle a, b, c as a polygon.
  static ClipPolygon triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
    ClipPolygon polygon;
    polygon.points[0] = a;
    polygon.points[1] = b;
    polygon.points[2] = c;
    polygon.size = 3;
    return polygon;
  }

  // Keeps the part with sign * (p[axis] - bound) <= 0.
  ClipPolygon clipped(int axis, double bound, double sign) const {
    ClipPolygon out;
    for (int n = 0; n < size; ++n) {
      const Vec3& p = points[n];
      const Vec3& q = points[(n + 1) % size];
      const double dp = sign * (p[axis] - bound), dq = sign * (q[axis] - bound);
      if (dp <= 0.0) out.points[out.size++] = p;
      if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0)) out.points[out.size++] = p + (dp / (dp - dq)) * (q - p);
    }
    return out;
  }
  ClipPolygon slab(int axis, double lo, double hi) const { return clipped(axis, lo, -1.0).clipped(axis, hi, 1.0); }
  /// The part inside the closed box [lo, hi].
  ClipPolygon box(const Vec3& lo, const Vec3& hi) const {
    ClipPolygon piece = *this;
    for (int axis = 0; axis < 3 && piece.size > 0; ++axis) piece = piece.slab(axis, lo[axis], hi[axis]);
    return piece;
  }
  double area() const {
    Vec3 sum = Vec3::Zero();
    for (int n = 1; n + 1 < size; ++n) sum += (points[n] - points[0]).cross(points[n + 1] - points[0]);
    return 0.5 * sum.norm();
  }
  std::pair<double, double> range(int axis) const {
    double lo = points[0][axis], hi = lo;
    for (int n = 1; n < size; ++n) {
      lo = std::min(lo, points[n][axis]);
      hi = std::max(hi, points[n][axis]);
    }
    return {lo, hi};
  }
};

}  // namespace dg
