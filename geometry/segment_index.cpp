#include "geometry/segment_index.h"

#include <algorithm>
#include <limits>

namespace dg {

Vec3 closest_point_on_segment(const Vec3& p, const Segment& s) {
  const Vec3 d = s[1] - s[0];
  const double length2 = d.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - s[0]).dot(d) / length2, 0.0, 1.0) : 0.0;
  return s[0] + t * d;
}

double curve_length(const std::vector<Segment>& curve) {
  double length = 0.0;
  for (const Segment& s : curve) length += (s[1] - s[0]).norm();
  return length;
}

SegmentIndex::SegmentIndex(const std::vector<Segment>& segments, double reach, double cell) : segments_(segments), cell_(cell) {
  for (std::uint32_t i = 0; i < segments.size(); ++i) {
    const CellKey lo = cell_key(segments[i][0].cwiseMin(segments[i][1]) - Vec3::Constant(reach), cell_);
    const CellKey hi = cell_key(segments[i][0].cwiseMax(segments[i][1]) + Vec3::Constant(reach), cell_);
    for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z) grid_[{x, y, z}].push_back(i);
  }
}

std::optional<Vec3> SegmentIndex::nearest(const Vec3& p, double enough) const {
  const auto found = grid_.find(cell_key(p, cell_));
  if (found == grid_.end()) return std::nullopt;
  std::optional<Vec3> best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::uint32_t i : found->second) {
    const Vec3 q = closest_point_on_segment(p, segments_[i]);
    const double distance = (q - p).norm();
    if (distance < best_distance) best_distance = distance, best = q;
    if (best_distance <= enough) break;
  }
  return best;
}

}  // namespace dg
