#include "geometry/tessellation_bend.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>
#include <utility>

namespace dg {
namespace {

double angle_degrees(const Vec3& a, const Vec3& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / std::numbers::pi;
}

struct SideOfEdge {
  std::uint32_t lo, hi, triangle;
};

}  // namespace

std::vector<double> triangle_bend_degrees(const TriangleMesh& mesh, std::span<const FeatureEdge> features) {
  std::vector<SideOfEdge> sides;
  sides.reserve(3 * mesh.triangles.size());
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = tri[k], b = tri[(k + 1) % 3];
      sides.push_back({std::min(a, b), std::max(a, b), t});
    }
  }
  std::sort(sides.begin(), sides.end(),
            [](const SideOfEdge& x, const SideOfEdge& y) { return std::tie(x.lo, x.hi, x.triangle) < std::tie(y.lo, y.hi, y.triangle); });
  auto is_feature = [&](std::uint32_t lo, std::uint32_t hi) {
    const auto it = std::lower_bound(features.begin(), features.end(), std::make_pair(lo, hi),
                                     [](const FeatureEdge& x, const std::pair<std::uint32_t, std::uint32_t>& key) {
                                       return std::make_pair(x.v0, x.v1) < key;
                                     });
    return it != features.end() && it->v0 == lo && it->v1 == hi;
  };
  std::vector<double> bend(mesh.triangles.size(), 0.0);
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i;
    while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi) ++j;
    if (j - i == 2 && !is_feature(sides[i].lo, sides[i].hi)) {
      const Vec3 a = mesh.area_vector(sides[i].triangle), b = mesh.area_vector(sides[i + 1].triangle);
      if (a.norm() > 0.0 && b.norm() > 0.0) {
        // Up to orientation: a flipped neighbour on a smooth surface is not a fold.
        const double angle = std::min(angle_degrees(a, b), angle_degrees(a, -b));
        bend[sides[i].triangle] = std::max(bend[sides[i].triangle], angle);
        bend[sides[i + 1].triangle] = std::max(bend[sides[i + 1].triangle], angle);
      }
    }
    i = j;
  }
  return bend;
}

std::vector<double> feature_edge_bend_degrees(const TriangleMesh& mesh, std::span<const FeatureEdge> features,
                                              double max_turn_degrees) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> at_vertex;  // (vertex, feature edge)
  at_vertex.reserve(2 * features.size());
  for (std::uint32_t e = 0; e < features.size(); ++e) {
    at_vertex.emplace_back(features[e].v0, e);
    at_vertex.emplace_back(features[e].v1, e);
  }
  std::sort(at_vertex.begin(), at_vertex.end());
  // Direction of edge e pointing away from vertex v.
  auto away_from = [&](std::uint32_t e, std::uint32_t v) {
    const FeatureEdge& edge = features[e];
    const std::uint32_t other = edge.v0 == v ? edge.v1 : edge.v0;
    return Vec3(mesh.positions[other] - mesh.positions[v]);
  };
  std::vector<double> bend(features.size(), 0.0);
  for (std::size_t i = 0; i < at_vertex.size();) {
    std::size_t j = i;
    while (j < at_vertex.size() && at_vertex[j].first == at_vertex[i].first) ++j;
    const std::uint32_t v = at_vertex[i].first;
    for (std::size_t a = i; a < j; ++a)
      for (std::size_t b = a + 1; b < j; ++b) {
        const std::uint32_t ea = at_vertex[a].second, eb = at_vertex[b].second;
        if (features[ea].kind != features[eb].kind) continue;
        const Vec3 da = away_from(ea, v), db = away_from(eb, v);
        if (da.norm() <= 0.0 || db.norm() <= 0.0) continue;
        const double turn = angle_degrees(da, -db);  // 0 when eb continues ea straight on
        if (turn >= max_turn_degrees) continue;
        bend[ea] = std::max(bend[ea], turn);
        bend[eb] = std::max(bend[eb], turn);
      }
    i = j;
  }
  return bend;
}

}  // namespace dg
