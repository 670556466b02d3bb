#pragma once
// Mean shift clustering with a flat kernel (Št'ava et al. 2010 §4.1 and §4.3 cluster similarity
// votes and transformation spaces with it).

#include <array>
#include <cstddef>
#include <vector>

namespace dg {

/// A point of up to four coordinates, already divided by the bandwidth (kernel radius 1).
using ShiftPoint = std::array<double, 4>;

/// Clusters of a mean shift run.
struct ShiftClusters {
  std::vector<int> labels;          ///< cluster of each point, -1 when no mode is within radius 1
  std::vector<ShiftPoint> centers;  ///< one mode per cluster
  std::vector<std::size_t> sizes;   ///< points per cluster
};

/// Mean shift of `points` using their first `dimensions` coordinates (1..4). `periods[k] > 0`
/// makes coordinate k periodic with that period (angles). Seeds are the occupied unit cells;
/// modes closer than 0.5 are merged; every point joins the nearest mode within radius 1.
/// Clusters are ordered by decreasing size, ties by center coordinates, so the result does not
/// depend on the order of the points.
ShiftClusters mean_shift(const std::vector<ShiftPoint>& points, int dimensions, const ShiftPoint& periods);

}  // namespace dg
