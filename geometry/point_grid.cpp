#include "geometry/point_grid.h"

#include <tbb/parallel_sort.h>

namespace dg {

PointGrid::PointGrid(std::span<const Vec3> points, double cell) : points_(points), cell_(cell) {
  std::vector<std::pair<CellKey, std::uint32_t>> keyed(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) keyed[i] = {cell_key(points[i], cell), static_cast<std::uint32_t>(i)};
  tbb::parallel_sort(keyed.begin(), keyed.end());  // pairs are distinct: the order is deterministic
  order_.reserve(keyed.size());
  for (std::size_t begin = 0; begin < keyed.size();) {
    std::size_t end = begin + 1;
    while (end < keyed.size() && keyed[end].first == keyed[begin].first) ++end;
    buckets_.emplace(keyed[begin].first, std::pair{static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end)});
    begin = end;
  }
  for (const auto& [key, index] : keyed) order_.push_back(index);
}

}  // namespace dg
