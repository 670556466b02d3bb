#pragma once
// Points bucketed in a uniform grid, for radius queries on point clouds.

#include "geometry/cell_key.h"
#include "geometry/types.h"

#include <cstdint>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

namespace dg {

class PointGrid {
 public:
  /// Buckets `points` (kept by reference) in cells of edge `cell` (model units); queries are
  /// cheapest for radii up to the cell.
  PointGrid(std::span<const Vec3> points, double cell);

  /// Calls visit(index, squared distance) for every point within `radius` of p, bucket by bucket
  /// in a fixed order (ascending index within a bucket).
  template <class Visit>
  void visit_within(const Vec3& p, double radius, Visit&& visit) const {
    any_within(p, radius, [&](std::uint32_t point, double d2) {
      visit(point, d2);
      return false;
    });
  }

  /// The same in the same order, stopping at the first point for which visit returns true;
  /// returns whether one did.
  template <class Visit>
  bool any_within(const Vec3& p, double radius, Visit&& visit) const {
    const double radius2 = radius * radius;
    const CellKey lo = cell_key(p - Vec3::Constant(radius), cell_), hi = cell_key(p + Vec3::Constant(radius), cell_);
    for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
          const auto found = buckets_.find({x, y, z});
          if (found == buckets_.end()) continue;
          for (std::uint32_t i = found->second.first; i < found->second.second; ++i) {
            const std::uint32_t point = order_[i];
            const double d2 = (points_[point] - p).squaredNorm();
            if (d2 <= radius2 && visit(point, d2)) return true;
          }
        }
    return false;
  }

  double cell() const { return cell_; }

 private:
  std::span<const Vec3> points_;
  double cell_;
  std::vector<std::uint32_t> order_;  // point indices sorted by cell
  std::unordered_map<CellKey, std::pair<std::uint32_t, std::uint32_t>, CellKeyHash> buckets_;  // cell -> range of order_
};

}  // namespace dg
