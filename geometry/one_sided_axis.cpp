#include "geometry/one_sided_axis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace dg {
namespace {

// Facing shares along all three axes of `count` items: normal_at(i) a unit normal, weight_at(i)
// its weight (area or 1).
template <class NormalAt, class WeightAt>
std::array<AxisFacing, 3> facing_shares(std::size_t count, NormalAt normal_at, WeightAt weight_at) {
  const double along = std::cos(kFacingDegrees * std::numbers::pi / 180.0);
  const double across = std::sin(kFacingDegrees * std::numbers::pi / 180.0);
  std::array<AxisFacing, 3> shares{AxisFacing{0}, AxisFacing{1}, AxisFacing{2}};
  double total = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const double weight = weight_at(i);
    if (!(weight > 0.0)) continue;
    const Vec3 n = normal_at(i);
    total += weight;
    for (AxisFacing& share : shares) {
      const double c = n[share.axis];
      if (c >= along) share.up += weight;
      else if (c <= -along) share.down += weight;
      else if (std::abs(c) <= across) share.across += weight;
    }
  }
  if (total > 0.0)
    for (AxisFacing& share : shares) share.up /= total, share.down /= total, share.across /= total;
  return shares;
}

}  // namespace

std::optional<AxisFacing> one_sided_up_axis(const Model& model) {
  std::array<AxisFacing, 3> shares;
  if (model.is_point_cloud()) {
    const PointCloud& cloud = model.cloud;
    if (!cloud.has_normals()) return std::nullopt;
    shares = facing_shares(
        cloud.positions.size(), [&](std::size_t i) { return cloud.normals[i].normalized(); },
        [&](std::size_t i) { return cloud.normals[i].norm() > 0.0 ? 1.0 : 0.0; });
  } else {
    const TriangleMesh& mesh = model.mesh;
    shares = facing_shares(
        mesh.triangles.size(), [&](std::size_t t) { return mesh.area_vector(t).normalized(); },
        [&](std::size_t t) { return mesh.area_vector(t).norm(); });
  }
  const Vec3 size = model.bounds().size();
  std::optional<AxisFacing> found;
  for (const AxisFacing& share : shares) {
    const double other = std::min(size[(share.axis + 1) % 3], size[(share.axis + 2) % 3]);
    const bool one_sided = share.up >= kOneSidedUp && share.down <= kOneSidedDown * share.up &&
                           share.across >= kOneSidedAcross && size[share.axis] >= kOneSidedHeight * other;
    if (!one_sided) continue;
    if (found) return std::nullopt;
    found = share;
  }
  return found;
}

}  // namespace dg
