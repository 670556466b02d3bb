#include "grammar/seam_plane.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace dg {
namespace {

// Directions a plane through a band may take: [0] perpendicular to the walls it crosses (the
// direction its surface normals leave out), [1] its flattest direction; and whether the walls
// decide (the normals leave one direction out).
struct BandDirections {
  std::array<Vec3, 2> normals{Vec3::UnitX(), Vec3::UnitX()};
  bool walls_decide = false;
  Vec3 mean = Vec3::Zero();
};

BandDirections band_directions(const VoxelSurface& surface, const std::vector<std::uint32_t>& site) {
  BandDirections result;
  for (std::uint32_t c : site) result.mean += surface.centre(c);
  result.mean /= static_cast<double>(std::max<std::size_t>(1, site.size()));
  Mat3 covariance = Mat3::Zero(), normals = Mat3::Zero();
  for (std::uint32_t c : site) {
    const Vec3 d = surface.centre(c) - result.mean;
    covariance += d * d.transpose();
    for (const CellPlane& p : surface.planes(c)) normals += p.normal * p.normal.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Mat3> across(normals);
  const Eigen::SelfAdjointEigenSolver<Mat3> flattest(covariance);
  result.walls_decide = across.eigenvalues()(0) < 0.05 * across.eigenvalues()(1);
  result.normals = {across.eigenvectors().col(0).normalized(), flattest.eigenvectors().col(0).normalized()};
  return result;
}

// Cell centres next to one location's band, in the seam's frame, on the docker's side or not,
// with the half thickness of a voxel along a seam-frame direction at that location.
struct BandNeighbours {
  std::vector<Vec3> docker, rest;
  Mat3 to_model = Mat3::Identity();  // seam-frame directions to model directions
};

BandNeighbours band_neighbours(const VoxelSurface& surface, const SeamLocation& location) {
  const std::vector<std::uint32_t>& site = *location.site;
  const std::vector<std::uint32_t>& docker = *location.docker;
  BandNeighbours result;
  result.to_model = location.to_seam.rotation.transpose();
  for (std::uint32_t c : site)
    for (std::uint32_t n : surface.neighbours(c)) {
      if (std::binary_search(site.begin(), site.end(), n)) continue;
      const Vec3 centre = location.to_seam.apply(surface.centre(n));
      if (std::binary_search(docker.begin(), docker.end(), n))
        result.docker.push_back(centre);
      else
        result.rest.push_back(centre);
    }
  return result;
}

}  // namespace

std::optional<Plane> fit_band_plane(const VoxelSurface& surface, const std::vector<std::uint32_t>& site, double flatness) {
  if (site.size() < 3) return std::nullopt;
  const BandDirections band = band_directions(surface, site);
  Plane plane{band.walls_decide ? band.normals[0] : band.normals[1], 0.0};
  plane.offset = plane.normal.dot(band.mean);
  for (std::uint32_t c : site)
    if (std::abs(plane.distance(surface.centre(c))) > flatness) return std::nullopt;
  return plane;
}

bool orient_towards_docker(const VoxelSurface& surface, const std::vector<std::uint32_t>& docker,
                           const std::vector<char>& site_mask, Plane& plane) {
  std::size_t positive = 0, negative = 0;
  for (std::uint32_t c : docker) {
    bool next_to_band = false;
    for (std::uint32_t n : surface.neighbours(c)) next_to_band = next_to_band || site_mask[n];
    if (!next_to_band) continue;
    const double d = plane.distance(surface.centre(c));
    if (d > 0) ++positive;
    if (d < 0) ++negative;
  }
  const std::size_t total = positive + negative;
  if (total == 0) return false;
  if (negative > positive) {
    plane.normal = -plane.normal;
    plane.offset = -plane.offset;
    std::swap(positive, negative);
  }
  return positive >= 0.8 * static_cast<double>(total);
}

std::optional<Plane> plane_between_sides(const VoxelSurface& surface, std::span<const SeamLocation> locations,
                                         double min_gap) {
  if (locations.empty() || locations.front().site->size() < 3) return std::nullopt;
  std::vector<BandNeighbours> sides;
  Vec3 docker_sum = Vec3::Zero(), rest_sum = Vec3::Zero();
  std::size_t docker_count = 0, rest_count = 0;
  for (const SeamLocation& location : locations) {
    sides.push_back(band_neighbours(surface, location));
    if (sides.back().docker.empty() || sides.back().rest.empty()) return std::nullopt;
    for (const Vec3& p : sides.back().docker) docker_sum += p, ++docker_count;
    for (const Vec3& p : sides.back().rest) rest_sum += p, ++rest_count;
  }
  // The first location's band directions are in the model frame: moved into the seam's.
  const BandDirections band = band_directions(surface, *locations.front().site);
  const Mat3& into_seam = locations.front().to_seam.rotation;
  std::vector<Vec3> normals{into_seam * band.normals[0], into_seam * band.normals[1], Vec3::UnitX(), Vec3::UnitY(),
                            Vec3::UnitZ()};
  const Vec3 apart = docker_sum / static_cast<double>(docker_count) - rest_sum / static_cast<double>(rest_count);
  if (apart.norm() > 0.0) normals.push_back(apart.normalized());

  const double half_voxel = 0.5 * surface.eps();
  std::optional<Plane> best;
  double best_gap = min_gap;
  for (const Vec3& candidate : normals)
    for (const Vec3& normal : {candidate, Vec3(-candidate)}) {
      // The plane must pass above every rest voxel and below every docker voxel.
      double low = -std::numeric_limits<double>::infinity(), high = std::numeric_limits<double>::infinity();
      for (const BandNeighbours& side : sides) {
        const double half = half_voxel * (side.to_model * normal).lpNorm<1>();
        for (const Vec3& p : side.rest) low = std::max(low, normal.dot(p) + half);
        for (const Vec3& p : side.docker) high = std::min(high, normal.dot(p) - half);
      }
      if (high - low <= best_gap) continue;
      best_gap = high - low;
      best = Plane{normal, 0.5 * (low + high)};
    }
  return best;
}

}  // namespace dg
