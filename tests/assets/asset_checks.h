#pragma once
// Helpers for the asset tests: exact-ish vertex lookup, signed volume, transforms,
// brute-force self-intersection count.

#include "geometry/mesh.h"

#include <cmath>
#include <cstdint>
#include <algorithm>
#include <map>
#include <numeric>
#include <nlohmann/json.hpp>
#include <tuple>
#include <vector>

namespace dg::assets::test {

/// Finds mesh vertices near a query point (within `tolerance`, default 1e-9 model units).
class VertexLookup {
 public:
  explicit VertexLookup(const std::vector<Vec3>& points, double tolerance = 1e-9) : points_(points), tolerance_(tolerance) {
    for (std::size_t i = 0; i < points.size(); ++i) cells_[key(points[i])].push_back(i);
  }
  /// True when some vertex lies within the tolerance of p.
  bool contains(const Vec3& p) const {
    const auto [x, y, z] = key(p);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find({x + dx, y + dy, z + dz});
          if (it == cells_.end()) continue;
          for (std::size_t i : it->second)
            if ((points_[i] - p).cwiseAbs().maxCoeff() <= tolerance_) return true;
        }
    return false;
  }

 private:
  using Key = std::tuple<std::int64_t, std::int64_t, std::int64_t>;
  Key key(const Vec3& p) const {
    const double cell = 1e-6;
    return {static_cast<std::int64_t>(std::floor(p.x() / cell)), static_cast<std::int64_t>(std::floor(p.y() / cell)),
            static_cast<std::int64_t>(std::floor(p.z() / cell))};
  }
  const std::vector<Vec3>& points_;
  double tolerance_;
  std::map<Key, std::vector<std::size_t>> cells_;
};

/// Signed volume enclosed by a closed mesh (positive when outward oriented), in m^3.
inline double signed_volume(const TriangleMesh& mesh) {
  double volume = 0.0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    volume += a.dot(b.cross(c)) / 6.0;
  }
  return volume;
}

/// A 4x4 matrix from its JSON rows.
inline Mat4 matrix_from_json(const nlohmann::json& rows) {
  Mat4 m;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) m(i, j) = rows.at(static_cast<std::size_t>(i)).at(static_cast<std::size_t>(j)).get<double>();
  return m;
}

/// Number of mesh vertices that `transform` maps onto some mesh vertex (within 1e-9).
inline std::size_t vertices_mapped_onto_vertices(const TriangleMesh& mesh, const Mat4& transform) {
  const VertexLookup lookup(mesh.positions);
  std::size_t hits = 0;
  for (const Vec3& p : mesh.positions) {
    const Vec3 q = transform.block<3, 3>(0, 0) * p + transform.block<3, 1>(0, 3);
    if (lookup.contains(q)) ++hits;
  }
  return hits;
}

/// True when segment p-q crosses the interior of triangle a b c (touching its border, or a
/// segment lying in its plane, does not count); `eps` is a length tolerance in model units.
inline bool segment_pierces_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c, double eps) {
  const Vec3 n = (b - a).cross(c - a);
  const double length = n.norm();
  if (length == 0.0) return false;
  const Vec3 unit = n / length;
  const double dp = unit.dot(p - a), dq = unit.dot(q - a);
  if ((dp > -eps && dq > -eps) || (dp < eps && dq < eps)) return false;  // same side, touching or coplanar
  const Vec3 x = p + (q - p) * (dp / (dp - dq));
  // Distances of x from the three edges, inside the triangle's plane.
  const Vec3 corners[3] = {a, b, c};
  for (int k = 0; k < 3; ++k) {
    const Vec3& u = corners[k];
    const Vec3& v = corners[(k + 1) % 3];
    if (unit.dot((v - u).cross(x - u)) / (v - u).norm() <= eps) return false;
  }
  return true;
}

/// Pairs of triangles without a common vertex where an edge of one crosses the other's interior.
inline std::size_t self_intersections(const TriangleMesh& mesh) {
  const double eps = 1e-9 * std::max(1.0, mesh.bounds().diagonal());
  const std::size_t count = mesh.triangles.size();
  std::vector<BoundingBox> boxes(count);
  for (std::size_t t = 0; t < count; ++t)
    for (const Vec3& p : mesh.corners(t)) boxes[t].add(p);
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return boxes[i].min.x() < boxes[j].min.x(); });
  std::size_t hits = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t s = order[i];
    for (std::size_t j = i + 1; j < count && boxes[order[j]].min.x() <= boxes[s].max.x() + eps; ++j) {
      const std::size_t t = order[j];
      if ((boxes[s].min.array() > boxes[t].max.array() + eps).any() || (boxes[t].min.array() > boxes[s].max.array() + eps).any()) continue;
      const Triangle& A = mesh.triangles[s];
      const Triangle& B = mesh.triangles[t];
      if (std::any_of(A.begin(), A.end(), [&](std::uint32_t v) { return std::find(B.begin(), B.end(), v) != B.end(); })) continue;
      const auto a = mesh.corners(s), b = mesh.corners(t);
      bool crossing = false;
      for (int k = 0; k < 3 && !crossing; ++k) {
        crossing = segment_pierces_triangle(a[k], a[(k + 1) % 3], b[0], b[1], b[2], eps) ||
                   segment_pierces_triangle(b[k], b[(k + 1) % 3], a[0], a[1], a[2], eps);
      }
      if (crossing) ++hits;
    }
  }
  return hits;
}

}  // namespace dg::assets::test
