#include "geometry/polygon_triangulation.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace dg {
namespace {

using Vec2 = Eigen::Vector2d;

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Whether p lies inside or on the counter-clockwise triangle (a, b, c), or outside by no more
// than `on` from its edges' lines.
bool inside_or_on(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c, double on) {
  return cross(b - a, p - a) >= -on * (b - a).norm() && cross(c - b, p - b) >= -on * (c - b).norm() &&
         cross(a - c, p - c) >= -on * (a - c).norm();
}

}  // namespace

std::vector<Triangle> fan(std::span<const std::uint32_t> corners) {
  std::vector<Triangle> triangles;
  for (std::size_t i = 1; i + 1 < corners.size(); ++i) triangles.push_back({corners[0], corners[i], corners[i + 1]});
  return triangles;
}

std::vector<Triangle> triangulate_polygon(const std::vector<Vec3>& positions, std::span<const std::uint32_t> input) {
  const std::size_t n = input.size();
  if (n <= 3 || n > kMaxClippedCorners) return fan(input);
  Vec3 normal = Vec3::Zero();  // Newell's normal: twice the area vector of the polygon
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = positions[input[i]];
    const Vec3& b = positions[input[(i + 1) % n]];
    normal += Vec3((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()), (a.x() - b.x()) * (a.y() + b.y()));
  }
  if (!(normal.norm() > 0.0) || !normal.allFinite()) return fan(input);
  normal.normalize();
  bool convex = true;
  for (std::size_t i = 0; i < n && convex; ++i) {
    const Vec3& a = positions[input[(i + n - 1) % n]];
    const Vec3& b = positions[input[i]];
    const Vec3& c = positions[input[(i + 1) % n]];
    convex = (b - a).cross(c - b).dot(normal) >= 0.0;
  }
  if (convex) return fan(input);

  // The same cycle read from its lowest corner (by x, then y, then z) towards its lower
  // neighbour: a back-to-back copy of the polygon (its corners in the opposite order, perhaps at
  // other vertices of the same positions) gets the same triangles, turned over, and stays
  // recognisable as a duplicate once vertices are welded.
  auto lower = [&](std::uint32_t a, std::uint32_t b) {
    const Vec3 &p = positions[a], &q = positions[b];
    return std::tie(p.x(), p.y(), p.z(), a) < std::tie(q.x(), q.y(), q.z(), b);
  };
  std::vector<std::uint32_t> corners(input.begin(), input.end());
  std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end(), lower), corners.end());
  const bool reversed = lower(corners[n - 1], corners[1]);
  if (reversed) {
    std::reverse(corners.begin() + 1, corners.end());
    normal = -normal;
  }
  const Vec3& first = positions[corners[0]];
  // In the polygon's plane, counter-clockwise seen from the normal.
  const Vec3 u = normal.unitOrthogonal(), v = normal.cross(u);
  std::vector<Vec2> points(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 p = positions[corners[i]] - first;
    points[i] = Vec2(p.dot(u), p.dot(v));
  }
  // Corners that stand out of the line through their neighbours by no more than this (1e-6 of
  // the polygon's extent, above float rounding of the file's coordinates) are flat, not ears, and
  // corners that near an ear's edge lie on it (block it): a run of collinear corners (a floor's
  // edge notched by column plinths, each notch corner on the line) clipped there, or skipped by
  // an ear whose diagonal passes a rounding's width beside them, leaves needle triangles of about
  // zero width whose normals point anywhere (and whose edges count as sharp), wherever the
  // clipping happened to pass.
  double extent = 0.0;
  for (std::size_t i = 1; i < n; ++i) extent = std::max(extent, (points[i] - points[0]).lpNorm<Eigen::Infinity>());
  const double flat_height = 1e-6 * extent;
  std::vector<std::size_t> remaining(n);
  for (std::size_t i = 0; i < n; ++i) remaining[i] = i;
  std::vector<Triangle> triangles;
  std::size_t start = 0;  // where the search for the next ear begins (after the last one clipped)
  while (remaining.size() > 3) {
    const std::size_t m = remaining.size();
    auto turn = [&](std::size_t k) {
      const Vec2& a = points[remaining[(k + m - 1) % m]];
      const Vec2& b = points[remaining[k]];
      const Vec2& c = points[remaining[(k + 1) % m]];
      return cross(b - a, c - b);
    };
    // An ear: a strictly convex corner whose triangle holds no other corner (corners at the same
    // position as one of its own, where a polygon runs around a hole and back, do not count).
    auto is_ear = [&](std::size_t k) {
      const std::size_t ia = remaining[(k + m - 1) % m], ib = remaining[k], ic = remaining[(k + 1) % m];
      const Vec2 &a = points[ia], &b = points[ib], &c = points[ic];
      if (!(turn(k) > flat_height * (c - a).norm())) return false;
      for (std::size_t j : remaining) {
        if (j == ia || j == ib || j == ic) continue;
        const Vec2& p = points[j];
        if (p == a || p == b || p == c) continue;
        if (inside_or_on(p, a, b, c, flat_height)) return false;
      }
      return true;
    };
    std::size_t clip = m;
    for (std::size_t step = 0; step < m && clip == m; ++step)
      if (is_ear((start + step) % m)) clip = (start + step) % m;
    if (clip == m) {  // no ear (self-intersecting or degenerate): the most convex corner
      clip = 0;
      for (std::size_t k = 1; k < m; ++k)
        if (turn(k) > turn(clip)) clip = k;
    }
    triangles.push_back({corners[remaining[(clip + m - 1) % m]], corners[remaining[clip]], corners[remaining[(clip + 1) % m]]});
    remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(clip));
    start = clip == 0 ? 0 : clip - 1;
  }
  triangles.push_back({corners[remaining[0]], corners[remaining[1]], corners[remaining[2]]});
  if (reversed)
    for (Triangle& t : triangles) std::swap(t[1], t[2]);
  return triangles;
}

}  // namespace dg
