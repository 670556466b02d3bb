#pragma once
// Line segments in space (curves as lists of them) and a hash of them by cell, to find the
// segment points near a point.

#include "geometry/cell_key.h"
#include "geometry/types.h"

#include <array>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

namespace dg {

using Segment = std::array<Vec3, 2>;

/// Closest point to p on segment s (its first end when the segment has length 0).
Vec3 closest_point_on_segment(const Vec3& p, const Segment& s);

/// Total length of a curve's segments (model units).
double curve_length(const std::vector<Segment>& curve);

/// The segments of a curve hashed by the cells (edge `cell`, model units) that lie within
/// `reach` of them. Keeps a reference to the segments.
class SegmentIndex {
 public:
  SegmentIndex(const std::vector<Segment>& segments, double reach, double cell);
  SegmentIndex(std::vector<Segment>&&, double, double) = delete;

  /// The point of the curve nearest to p among the segments hashed at p's cell (nothing when
  /// none is: then none lies within `reach`), or the first point found within `enough` of p
  /// (for a caller that only needs to know the distance is at most that; at 0, still the nearest).
  std::optional<Vec3> nearest(const Vec3& p, double enough = 0.0) const;

 private:
  const std::vector<Segment>& segments_;
  double cell_;
  std::unordered_map<CellKey, std::vector<std::uint32_t>, CellKeyHash> grid_;
};

}  // namespace dg
