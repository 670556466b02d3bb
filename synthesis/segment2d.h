#pragma once
// Small exact-enough 2D helpers on points and segments (y-up drawing units), shared by guides
// and the spatial index of guided growth.

#include "geometry/types.h"

#include <optional>
#include <vector>

namespace dg {

/// z of the cross product a x b.
inline double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Parameter u in [0, 1] of the point of segment [a, b] closest to p.
double closest_parameter(const Vec2& p, const Vec2& a, const Vec2& b);

/// Distance from p to the segment [a, b].
double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b);

/// Where segment [p, q] crosses segment [a, b]: the parameters s along [p, q] and u along
/// [a, b] (both in [0, 1]), or nothing when they do not meet or are parallel. End points count
/// with a relative slack of 1e-9 of the parameters.
struct SegmentCrossing {
  double s = 0;
  double u = 0;
};
std::optional<SegmentCrossing> cross_segments(const Vec2& p, const Vec2& q, const Vec2& a, const Vec2& b);

/// True when p lies inside the closed polygon (even-odd rule; points on the boundary may go
/// either way).
bool point_in_polygon(const Vec2& p, const std::vector<Vec2>& polygon);

/// True when two edges of the closed polygon that are not neighbours meet, or two neighbours
/// overlap (fold back), or an edge has zero length. O(n^2); guides are small.
bool polygon_self_intersects(const std::vector<Vec2>& polygon);

/// Signed area (positive when the vertices run counter-clockwise).
double polygon_signed_area(const std::vector<Vec2>& polygon);

/// Signed angle in degrees (counter-clockwise positive, in (-180, 180]) that turns the heading
/// `heading_deg` toward the direction `to`.
double turn_toward(double heading_deg, const Vec2& to);

/// Unit vector of the heading (degrees counter-clockwise from +x).
Vec2 heading_vector(double heading_deg);

}  // namespace dg
