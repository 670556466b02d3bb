#include "grammar/seam_curve.h"

#include "geometry/cell_key.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace dg {
namespace {

double distance_to_segment(const Vec3& p, const Segment& s) {
  const Vec3 d = s[1] - s[0];
  const double length2 = d.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - s[0]).dot(d) / length2, 0.0, 1.0) : 0.0;
  return (s[0] + t * d - p).norm();
}

// The largest distance from a sample of `a` (segment ends and midpoints) to the nearest
// segment of `b`, or infinity when some sample has no segment of `b` within `limit`.
double farthest_sample(const std::vector<Segment>& a, const std::vector<Segment>& b, double limit, double cell) {
  auto key = [&](const Vec3& p) { return cell_key(p, cell); };
  std::unordered_map<CellKey, std::vector<std::uint32_t>, CellKeyHash> grid;
  for (std::uint32_t i = 0; i < b.size(); ++i) {
    const CellKey lo = key(b[i][0].cwiseMin(b[i][1]) - Vec3::Constant(limit));
    const CellKey hi = key(b[i][0].cwiseMax(b[i][1]) + Vec3::Constant(limit));
    for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z) grid[{x, y, z}].push_back(i);
  }
  constexpr double kFar = std::numeric_limits<double>::infinity();
  double farthest = 0.0;
  for (const Segment& s : a)
    for (const Vec3& p : {s[0], s[1], Vec3(0.5 * (s[0] + s[1]))}) {
      const auto found = grid.find(key(p));
      if (found == grid.end()) return kFar;
      double nearest = kFar;
      for (std::uint32_t i : found->second) nearest = std::min(nearest, distance_to_segment(p, b[i]));
      if (nearest > limit) return kFar;
      farthest = std::max(farthest, nearest);
    }
  return farthest;
}

}  // namespace

std::vector<Segment> seam_segments(const TriangleMesh& mesh, const EdgeUsers& users,
                                   const std::vector<std::uint32_t>& piece, const std::vector<char>& inside) {
  std::vector<Segment> segments;
  for (std::uint32_t t : piece)
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t corner = 3 * t + k;
      bool meets_outside = false;
      for (std::uint32_t u = users.group_begin[corner]; u < users.group_end[corner] && !meets_outside; ++u)
        meets_outside = !inside[users.corners[u] / 3];
      if (!meets_outside) continue;
      segments.push_back({mesh.positions[mesh.triangles[t][k]], mesh.positions[mesh.triangles[t][(k + 1) % 3]]});
    }
  return segments;
}

double seam_misfit(const std::vector<Segment>& a, const std::vector<Segment>& b, double limit, double cell) {
  return std::max(farthest_sample(a, b, limit, cell), farthest_sample(b, a, limit, cell));
}

}  // namespace dg
