#include "geometry/cloud_statistics.h"

#include "geometry/errors.h"
#include "geometry/point_grid.h"

#include <Eigen/Eigenvalues>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace dg {

double typical_point_spacing(const PointCloud& cloud, double max_distance, std::size_t k, std::size_t probes) {
  if (cloud.positions.empty()) throw InputError("the point cloud has no points");
  if (!(max_distance > 0.0) || !std::isfinite(max_distance)) throw InputError("point spacing needs a positive cap");
  const PointGrid grid(cloud.positions, max_distance);
  const std::size_t n = cloud.positions.size(), count = std::min(n, std::max<std::size_t>(probes, 1));
  std::vector<double> distances(count);
  tbb::parallel_for(std::size_t{0}, count, [&](std::size_t i) {
    const std::size_t point = i * n / count;
    std::vector<double> nearest;
    grid.visit_within(cloud.positions[point], max_distance, [&](std::uint32_t other, double d2) {
      if (other != point) nearest.push_back(d2);
    });
    if (nearest.size() < k) {
      distances[i] = max_distance;
      return;
    }
    std::nth_element(nearest.begin(), nearest.begin() + static_cast<std::ptrdiff_t>(k - 1), nearest.end());
    distances[i] = std::sqrt(nearest[k - 1]);
  });
  std::nth_element(distances.begin(), distances.begin() + static_cast<std::ptrdiff_t>(count / 2), distances.end());
  return distances[count / 2];
}

double typical_point_noise(const PointCloud& cloud, double radius, std::size_t probes) {
  if (cloud.positions.empty()) throw InputError("the point cloud has no points");
  if (!(radius > 0.0) || !std::isfinite(radius)) throw InputError("point noise needs a positive radius");
  const PointGrid grid(cloud.positions, radius);
  const std::size_t n = cloud.positions.size(), count = std::min(n, std::max<std::size_t>(probes, 1));
  std::vector<double> rms(count, -1.0);
  tbb::parallel_for(std::size_t{0}, count, [&](std::size_t i) {
    std::vector<Vec3> near;
    grid.visit_within(cloud.positions[i * n / count], radius, [&](std::uint32_t other, double) {
      near.push_back(cloud.positions[other]);
    });
    if (near.size() < 11) return;
    Vec3 centroid = Vec3::Zero();
    for (const Vec3& p : near) centroid += p;
    centroid /= static_cast<double>(near.size());
    Mat3 covariance = Mat3::Zero();
    for (const Vec3& p : near) covariance += (p - centroid) * (p - centroid).transpose();
    const Eigen::SelfAdjointEigenSolver<Mat3> solver(covariance);
    rms[i] = std::sqrt(std::max(0.0, solver.eigenvalues()[0]) / static_cast<double>(near.size()));
  });
  std::erase_if(rms, [](double value) { return value < 0.0; });
  if (rms.empty()) return 0.0;
  const auto median = rms.begin() + static_cast<std::ptrdiff_t>(rms.size() / 2);
  std::nth_element(rms.begin(), median, rms.end());
  return *median;
}

}  // namespace dg
