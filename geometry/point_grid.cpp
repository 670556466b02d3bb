#include "geometry/point_grid.h"

#include <algorithm>
#include <numeric>

namespace dg {

PointGrid::PointGrid(std::span<const Vec3> points, double cell) : points_(points), cell_(cell) {
  std::vector<CellKey> keys(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) keys[i] = cell_key(points[i], cell);
  order_.resize(points.size());
  std::iota(order_.begin(), order_.end(), 0u);
  std::stable_sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
  for (std::size_t begin = 0; begin < order_.size();) {
    std::size_t end = begin + 1;
    while (end < order_.size() && keys[order_[end]] == keys[order_[begin]]) ++end;
    buckets_.emplace(keys[order_[begin]], std::pair{static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end)});
    begin = end;
  }
}

}  // namespace dg
