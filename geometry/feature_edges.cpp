#include "geometry/feature_edges.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dg {
namespace {

struct HalfEdge {
  std::uint32_t lo, hi;    // undirected key
  std::uint32_t triangle;  // owning triangle
  std::uint32_t opposite;  // vertex of the triangle not on the edge
};

// Triangles with the same vertex set as an earlier triangle are skipped.
std::vector<bool> first_of_duplicates(const TriangleMesh& mesh) {
  std::vector<std::pair<Triangle, std::uint32_t>> keyed(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    Triangle key = mesh.triangles[t];
    std::sort(key.begin(), key.end());
    keyed[t] = {key, static_cast<std::uint32_t>(t)};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<bool> keep(mesh.triangles.size(), true);
  for (std::size_t i = 1; i < keyed.size(); ++i)
    if (keyed[i].first == keyed[i - 1].first) keep[keyed[i].second] = false;
  return keep;
}

}  // namespace

std::vector<FeatureEdge> find_feature_edges(const TriangleMesh& mesh, double sharp_angle_degrees,
                                            std::span<const std::uint32_t> material_classes) {
  const std::vector<bool> keep = first_of_duplicates(mesh);
  std::vector<Vec3> normals(mesh.triangles.size());
  std::vector<HalfEdge> half_edges;
  half_edges.reserve(3 * mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!keep[t]) continue;
    const Vec3 n = mesh.area_vector(t);
    normals[t] = n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::Zero();
    const Triangle& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = tri[k], b = tri[(k + 1) % 3];
      half_edges.push_back({std::min(a, b), std::max(a, b), static_cast<std::uint32_t>(t), tri[(k + 2) % 3]});
    }
  }
  std::sort(half_edges.begin(), half_edges.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return std::tie(x.lo, x.hi, x.triangle) < std::tie(y.lo, y.hi, y.triangle);
  });

  const double cos_threshold = std::cos(sharp_angle_degrees * std::numbers::pi / 180.0);
  std::vector<FeatureEdge> result;
  for (std::size_t i = 0; i < half_edges.size();) {
    std::size_t j = i;
    while (j < half_edges.size() && half_edges[j].lo == half_edges[i].lo && half_edges[j].hi == half_edges[i].hi) ++j;
    FeatureEdge edge;
    edge.v0 = half_edges[i].lo;
    edge.v1 = half_edges[i].hi;
    Vec3 normal_sum = Vec3::Zero();
    for (std::size_t k = i; k < j; ++k) normal_sum += normals[half_edges[k].triangle];
    edge.normal = normal_sum.norm() > 0.0 ? Vec3(normal_sum.normalized()) : normals[half_edges[i].triangle];
    const std::size_t count = j - i;
    bool is_feature = true;
    if (count == 1) {
      edge.kind = EdgeKind::boundary;
    } else if (count >= 3) {
      edge.kind = EdgeKind::non_manifold;
    } else {
      const Vec3& n0 = normals[half_edges[i].triangle];
      const Vec3& n1 = normals[half_edges[i + 1].triangle];
      const double cosine = std::clamp(n0.dot(n1), -1.0, 1.0);
      edge.kind = EdgeKind::sharp;
      edge.dihedral_degrees = std::acos(cosine) * 180.0 / std::numbers::pi;
      // Concave when the opposite vertex of one face lies in front of the other face.
      const Vec3 to_opposite = mesh.positions[half_edges[i + 1].opposite] - mesh.positions[edge.v0];
      if (n0.dot(to_opposite) > 0.0) edge.dihedral_degrees = -edge.dihedral_degrees;
      is_feature = cosine < cos_threshold;
      if (!is_feature && !material_classes.empty() && mesh.has_materials() &&
          material_classes[mesh.materials[half_edges[i].triangle]] !=
              material_classes[mesh.materials[half_edges[i + 1].triangle]]) {
        edge.kind = EdgeKind::material;
        is_feature = true;
      }
    }
    if (is_feature) result.push_back(edge);
    i = j;
  }
  return result;
}

}  // namespace dg
