#include "symmetry/cloud_keypoints.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace dg {
namespace {

struct Neighbourhood {
  Vec3 centroid = Vec3::Zero();
  Mat3 covariance = Mat3::Zero();
  std::size_t count = 0;
};

// Points of `cells` (and, with `ring`, of their neighbours).
Neighbourhood gather(const PointCloud& cloud, const VoxelSurface& surface, std::uint32_t cell, int rings) {
  std::vector<std::uint32_t> cells{cell};
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<std::uint32_t> grown = cells;
    for (std::uint32_t c : cells)
      for (std::uint32_t n : surface.neighbours(c)) grown.push_back(n);
    std::sort(grown.begin(), grown.end());
    grown.erase(std::unique(grown.begin(), grown.end()), grown.end());
    cells = std::move(grown);
  }
  Neighbourhood n;
  for (std::uint32_t c : cells)
    for (std::uint32_t p : surface.points(c)) {
      n.centroid += cloud.positions[p];
      ++n.count;
    }
  if (n.count == 0) return n;
  n.centroid /= static_cast<double>(n.count);
  for (std::uint32_t c : cells)
    for (std::uint32_t p : surface.points(c)) {
      const Vec3 d = cloud.positions[p] - n.centroid;
      n.covariance += d * d.transpose();
    }
  return n;
}

}  // namespace

std::vector<Keypoint> cloud_keypoints(const PointCloud& cloud, const VoxelSurface& surface, const CloudKeypointOptions& options) {
  const std::size_t cells = surface.cell_count();
  std::vector<double> variation(cells, 0.0);
  std::vector<Neighbourhood> local(cells);
  for (std::uint32_t c = 0; c < cells; ++c) {
    local[c] = gather(cloud, surface, c, 1);
    if (local[c].count < options.min_points) continue;
    const Eigen::SelfAdjointEigenSolver<Mat3> solver(local[c].covariance);
    const Vec3 lambda = solver.eigenvalues().cwiseMax(0.0);
    const double sum = lambda.sum();
    variation[c] = sum > 0.0 ? lambda(0) / sum : 0.0;
  }
  std::vector<Keypoint> keypoints;
  for (std::uint32_t c = 0; c < cells; ++c) {
    if (variation[c] < options.min_variation) continue;
    // Peaks over two rings of cells: corners where creases meet, not arbitrary crease points.
    bool peak = true;
    for (std::uint32_t n1 : surface.neighbours(c)) {
      for (std::uint32_t n : surface.neighbours(n1))
        peak = peak && (n == c || variation[n] < variation[c] || (variation[n] == variation[c] && n > c));
      peak = peak && (variation[n1] < variation[c] || (variation[n1] == variation[c] && n1 > c));
    }
    if (!peak) continue;
    // Frame from the planes around the bend: the normals of flat cells within two rings,
    // oriented away from the wide centroid and clustered; the two largest clusters A and B
    // give normal = A, tangent = B made orthogonal to A (and the same with A, B swapped).
    const Neighbourhood wide = gather(cloud, surface, c, 2);
    std::vector<std::pair<Vec3, std::size_t>> clusters;  // summed normal, count
    std::vector<std::uint32_t> around{c};
    for (std::uint32_t n1 : surface.neighbours(c)) {
      around.push_back(n1);
      for (std::uint32_t n2 : surface.neighbours(n1)) around.push_back(n2);
    }
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    for (std::uint32_t k : around) {
      if (local[k].count < options.min_points || variation[k] > options.max_flat_variation) continue;
      const Eigen::SelfAdjointEigenSolver<Mat3> flat(local[k].covariance);
      Vec3 n = flat.eigenvectors().col(0).normalized();
      if (n.dot(local[k].centroid - wide.centroid) < 0.0) n = -n;
      auto it = std::find_if(clusters.begin(), clusters.end(),
                             [&](const auto& cl) { return cl.first.normalized().dot(n) > std::cos(0.26); });
      if (it == clusters.end())
        clusters.push_back({n, 1});
      else
        it->first += n, ++it->second;
    }
    std::stable_sort(clusters.begin(), clusters.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
    if (clusters.size() < 2) continue;
    const Vec3 a = clusters[0].first.normalized();
    const auto second = std::find_if(clusters.begin() + 1, clusters.end(),
                                     [&](const auto& cl) { return std::abs(cl.first.normalized().dot(a)) < std::cos(0.5); });
    if (second == clusters.end()) continue;
    const Vec3 b = second->first.normalized();
    for (const auto& [normal, other] : {std::pair<Vec3, Vec3>{a, b}, std::pair<Vec3, Vec3>{b, a}}) {
      const Vec3 tangent = (other - other.dot(normal) * normal).normalized();
      Keypoint k{local[c].centroid, tangent, normal, tangent.cross(normal), {}};
      k.descriptor.dihedral_degrees = std::acos(std::clamp(a.dot(b), -1.0, 1.0)) * 180.0 / 3.14159265358979323846;
      keypoints.push_back(k);
    }
  }
  return keypoints;
}

}  // namespace dg
