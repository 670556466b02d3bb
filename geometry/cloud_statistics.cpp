#include "geometry/cloud_statistics.h"

#include "geometry/errors.h"
#include "geometry/point_grid.h"

#include <Eigen/Eigenvalues>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace dg {
namespace {

constexpr std::size_t kSpacingNeighbour = 4;  // the k-th nearest point measures the spacing
constexpr std::size_t kNoiseNeighbours = 11;  // points (the probe's included) a plane fit needs

// Median of `values` (reordered); 0 when empty.
double median(std::vector<double>& values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// Root-mean-square distance of `points` to their least-squares plane; -1 when there are fewer
// than kNoiseNeighbours.
double plane_rms(const std::vector<Vec3>& points) {
  if (points.size() < kNoiseNeighbours) return -1.0;
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  Mat3 covariance = Mat3::Zero();
  for (const Vec3& p : points) covariance += (p - centroid) * (p - centroid).transpose();
  const Eigen::SelfAdjointEigenSolver<Mat3> solver(covariance);
  return std::sqrt(std::max(0.0, solver.eigenvalues()[0]) / static_cast<double>(points.size()));
}

}  // namespace

PointStatistics point_statistics(const PointCloud& cloud, double radius, std::size_t probes) {
  if (cloud.positions.empty()) throw InputError("the point cloud has no points");
  if (!(radius > 0.0) || !std::isfinite(radius)) throw InputError("point statistics need a positive radius");
  const PointGrid grid(cloud.positions, 2.0 * radius);
  const std::size_t n = cloud.positions.size(), count = std::min(n, std::max<std::size_t>(probes, 1));
  std::vector<double> spacings(count), rms(count, -1.0), rms_wide(count, -1.0);
  tbb::parallel_for(std::size_t{0}, count, [&](std::size_t i) {
    const std::size_t point = i * n / count;
    std::vector<double> others;  // squared distances within the radius
    std::vector<Vec3> near, wide;
    grid.visit_within(cloud.positions[point], 2.0 * radius, [&](std::uint32_t other, double d2) {
      wide.push_back(cloud.positions[other]);
      if (d2 > radius * radius) return;
      near.push_back(cloud.positions[other]);
      if (other != point) others.push_back(d2);
    });
    if (others.size() < kSpacingNeighbour) {
      spacings[i] = radius;
    } else {
      std::nth_element(others.begin(), others.begin() + static_cast<std::ptrdiff_t>(kSpacingNeighbour - 1), others.end());
      spacings[i] = std::sqrt(others[kSpacingNeighbour - 1]);
    }
    rms[i] = plane_rms(near);
    rms_wide[i] = plane_rms(wide);
  });
  std::erase_if(rms, [](double value) { return value < 0.0; });
  std::erase_if(rms_wide, [](double value) { return value < 0.0; });
  return {median(spacings), median(rms), median(rms_wide)};
}

}  // namespace dg
