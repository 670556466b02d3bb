#pragma once
// Helpers for the asset tests: exact-ish vertex lookup, signed volume, transforms.

#include "geometry/mesh.h"

#include <cmath>
#include <cstdint>
#include <map>
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

}  // namespace dg::assets::test
