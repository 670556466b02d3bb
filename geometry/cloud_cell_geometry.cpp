#include "geometry/cloud_cell_geometry.h"

#include <Eigen/Eigenvalues>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace dg {
namespace {

// A block whose points lie within this many times the noise floor of its plane (root mean
// square) is flat.
constexpr double kFlatNoiseFactor = 1.2;

struct BlockFit {
  CellPlane plane;
  double variation = 1.0;  ///< lambda0 / sum of eigenvalues; 1 = not fitted
  double rms = 0.0;        ///< root mean square distance of the points to the plane
  double farthest = 0.0;   ///< largest distance of a point to the plane
  double spread = 0.0;     ///< lambda1 / lambda2: near 0 when the points lie along a line
  std::size_t count = 0;
};

// Flips n so that its first clearly non-zero component is positive.
Vec3 canonical_normal(const Vec3& n) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(n[k]) > 1e-9) return n[k] > 0.0 ? n : Vec3(-n);
  return n;
}

// Least-squares plane of the points (principal axis of least variance through the centroid).
BlockFit fit_plane(const PointCloud& cloud, const std::vector<std::uint32_t>& points) {
  BlockFit fit;
  fit.count = points.size();
  if (points.size() < 3) return fit;
  Vec3 centroid = Vec3::Zero();
  for (std::uint32_t p : points) centroid += cloud.positions[p];
  centroid /= static_cast<double>(points.size());
  Mat3 covariance = Mat3::Zero();
  for (std::uint32_t p : points) {
    const Vec3 d = cloud.positions[p] - centroid;
    covariance += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Mat3> solver(covariance);
  const Vec3 lambda = solver.eigenvalues().cwiseMax(0.0);
  const double sum = lambda.sum();
  if (!(sum > 0.0)) return fit;
  const Vec3 normal = canonical_normal(solver.eigenvectors().col(0).normalized());
  fit.plane = {normal, normal.dot(centroid)};
  fit.variation = lambda(0) / sum;
  fit.spread = lambda(2) > 0.0 ? lambda(1) / lambda(2) : 0.0;
  fit.rms = std::sqrt(lambda(0) / static_cast<double>(points.size()));
  for (std::uint32_t p : points) fit.farthest = std::max(fit.farthest, std::abs(normal.dot(cloud.positions[p]) - fit.plane.offset));
  return fit;
}

// Points of a cell and its 26-neighbours, ascending.
std::vector<std::uint32_t> block_points(const VoxelSurface& surface, std::uint32_t cell) {
  std::vector<std::uint32_t> points(surface.points(cell).begin(), surface.points(cell).end());
  for (std::uint32_t n : surface.neighbours(cell)) points.insert(points.end(), surface.points(n).begin(), surface.points(n).end());
  std::sort(points.begin(), points.end());
  return points;
}

double distance(const CellPlane& plane, const Vec3& p) { return std::abs(plane.normal.dot(p) - plane.offset); }

bool same_plane(const CellPlane& a, const CellPlane& b, double cos_tolerance, double tolerance) {
  const double dot = a.normal.dot(b.normal);
  return std::abs(dot) > cos_tolerance && std::abs(a.offset - (dot > 0.0 ? b.offset : -b.offset)) < tolerance;
}

// The crease of two planes as the line point closest to `centre`, or nothing when parallel.
bool crease(const CellPlane& a, const CellPlane& b, const Vec3& centre, CellLine& line) {
  const Vec3 direction = a.normal.cross(b.normal);
  const double length = direction.norm();
  if (length < 1e-6) return false;
  line.direction = canonical_normal(direction / length);
  // Solve n_a . x = o_a, n_b . x = o_b, d . x = d . centre.
  Mat3 system;
  system.row(0) = a.normal.transpose();
  system.row(1) = b.normal.transpose();
  system.row(2) = line.direction.transpose();
  line.point = system.partialPivLu().solve(Vec3(a.offset, b.offset, line.direction.dot(centre)));
  line.kind = EdgeKind::sharp;
  return true;
}

}  // namespace

std::vector<CloudCell> fit_cloud_cells(const PointCloud& cloud, const VoxelSurface& surface, const CloudCellOptions& options) {
  const std::size_t cells = surface.cell_count();
  const double eps = surface.eps();
  std::vector<BlockFit> blocks(cells);
  tbb::parallel_for(std::size_t(0), cells, [&](std::size_t c) {
    const std::vector<std::uint32_t> points = block_points(surface, static_cast<std::uint32_t>(c));
    if (points.size() >= options.min_points) blocks[c] = fit_plane(cloud, points);
  });
  // Scan noise spreads even a flat block's points: the lower quartile of the blocks' distances
  // to their planes (most blocks of a scanned object are flat) is the noise floor, and a block
  // whose points lie no farther than kFlatNoiseFactor times it from its plane counts as flat too.
  std::vector<double> spreads;
  for (const BlockFit& block : blocks)
    if (block.count >= options.min_points && block.variation < 1.0) spreads.push_back(block.rms);
  double noise_floor = 0.0;
  if (!spreads.empty()) {
    std::nth_element(spreads.begin(), spreads.begin() + spreads.size() / 4, spreads.end());
    noise_floor = spreads[spreads.size() / 4];
  }
  auto nearly_flat = [&](std::uint32_t c) {
    return blocks[c].count >= options.min_points &&
           (blocks[c].variation < options.flat_variation || blocks[c].rms <= kFlatNoiseFactor * noise_floor);
  };

  // Noise: the median distance of points to their flat block's plane sets the inlier tolerance.
  std::vector<double> residuals;
  for (std::uint32_t c = 0; c < cells; ++c)
    if (nearly_flat(c)) residuals.push_back(blocks[c].rms);
  double noise = 0.0;
  if (!residuals.empty()) {
    std::nth_element(residuals.begin(), residuals.begin() + residuals.size() / 2, residuals.end());
    noise = residuals[residuals.size() / 2];
  }
  const double tolerance = std::max(options.min_inlier_tolerance_eps * eps, 3.0 * noise);
  const double cos_same = std::cos(3.0 * std::numbers::pi / 180.0);
  const double cos_crease = std::cos(options.min_crease_angle_degrees * std::numbers::pi / 180.0);
  const double half_diagonal = 0.5 * std::sqrt(3.0) * eps;
  // Flat: every point of the block on its plane (a few points of a second surface would tilt it).
  auto flat = [&](std::uint32_t c) { return nearly_flat(c) && blocks[c].farthest < tolerance; };

  std::vector<CloudCell> result(cells);
  tbb::parallel_for(std::size_t(0), cells, [&](std::size_t index) {
    const auto c = static_cast<std::uint32_t>(index);
    CloudCell& out = result[c];
    if (flat(c)) {
      out.planes.push_back(blocks[c].plane);
      return;
    }
    const Vec3 centre = surface.centre(c);
    // Candidate planes: flat blocks within two rings that pass through this voxel.
    std::vector<std::uint32_t> around(surface.neighbours(c).begin(), surface.neighbours(c).end());
    for (std::uint32_t n1 : surface.neighbours(c)) around.insert(around.end(), surface.neighbours(n1).begin(), surface.neighbours(n1).end());
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    std::vector<CellPlane> candidates;
    auto consider = [&](const CellPlane& plane) {
      const bool known = std::any_of(candidates.begin(), candidates.end(),
                                     [&](const CellPlane& p) { return same_plane(p, plane, cos_same, tolerance); });
      if (!known) candidates.push_back(plane);
    };
    for (std::uint32_t k : around)
      if (flat(k)) consider(blocks[k].plane);
    // Strips narrower than a block (a window reveal) have no flat block: planes through point
    // triples of the block, picked by a fixed generator seeded with the cell (deterministic).
    const std::vector<std::uint32_t> points = block_points(surface, c);
    std::uint64_t state = 0x9E3779B97F4A7C15ull ^ c;
    auto next = [&](std::size_t n) {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      return static_cast<std::size_t>((state >> 33) % n);
    };
    const double min_twice_area = 0.1 * eps * eps;
    // Triples of nearby points (within about a voxel of the first) mostly share a surface.
    std::vector<std::uint32_t> close;
    for (std::size_t trial = 0; points.size() >= 3 && trial < options.triple_trials; ++trial) {
      const Vec3& a = cloud.positions[points[next(points.size())]];
      close.clear();
      for (std::uint32_t p : points)
        if ((cloud.positions[p] - a).squaredNorm() < 1.5 * eps * eps) close.push_back(p);
      if (close.size() < 3) continue;
      const Vec3& b = cloud.positions[close[next(close.size())]];
      const Vec3& d = cloud.positions[close[next(close.size())]];
      const Vec3 normal = (b - a).cross(d - a);
      if (normal.norm() < min_twice_area) continue;
      const Vec3 unit = canonical_normal(normal.normalized());
      consider({unit, unit.dot(a)});
    }
    // Greedy cover of the block's points; each chosen plane is refitted to its own points and
    // kept when it passes through the voxel (the block also holds surfaces of neighbours only).
    std::vector<char> explained(points.size(), 0);
    const std::size_t min_new = std::max<std::size_t>(options.min_plane_points, points.size() / 12);
    for (std::size_t chosen_count = 0; chosen_count < 4; ++chosen_count) {
      std::size_t best = candidates.size(), best_count = 0;
      for (std::size_t k = 0; k < candidates.size(); ++k) {
        std::size_t count = 0;
        for (std::size_t i = 0; i < points.size(); ++i)
          count += !explained[i] && distance(candidates[k], cloud.positions[points[i]]) < tolerance ? 1 : 0;
        if (count > best_count) best = k, best_count = count;
      }
      if (best == candidates.size() || best_count < min_new) break;
      std::vector<std::uint32_t> inliers;
      for (std::size_t i = 0; i < points.size(); ++i)
        if (distance(candidates[best], cloud.positions[points[i]]) < tolerance) {
          inliers.push_back(points[i]);
          explained[i] = 1;
        }
      const BlockFit refit = fit_plane(cloud, inliers);
      const CellPlane chosen = candidates[best];
      candidates.erase(candidates.begin() + static_cast<std::ptrdiff_t>(best));
      if (refit.spread < options.min_spread) continue;  // points along a line: no surface of its own
      const bool better = refit.count >= options.min_points && std::abs(refit.plane.normal.dot(chosen.normal)) > cos_same;
      const CellPlane& plane = better ? refit.plane : chosen;
      if (distance(plane, centre) <= half_diagonal + tolerance && out.planes.size() < 3) out.planes.push_back(plane);
    }
    if (out.planes.empty()) {
      if (blocks[c].variation < 1.0) out.planes.push_back(blocks[c].plane);
      return;
    }
    for (std::size_t a = 0; a < out.planes.size(); ++a)
      for (std::size_t b = a + 1; b < out.planes.size(); ++b) {
        if (std::abs(out.planes[a].normal.dot(out.planes[b].normal)) > cos_crease) continue;
        CellLine line;
        if (crease(out.planes[a], out.planes[b], centre, line) && (line.point - centre).norm() <= half_diagonal)
          out.lines.push_back(line);
      }
  });
  return result;
}

std::vector<Vec3> cell_plane_normals(const PointCloud& cloud, const VoxelSurface& surface) {
  std::vector<Vec3> normals(cloud.positions.size(), Vec3::UnitZ());
  tbb::parallel_for(std::size_t{0}, cloud.positions.size(), [&](std::size_t i) {
    const Vec3& p = cloud.positions[i];
    const std::int64_t cell = surface.find(surface.voxel_of(p));
    if (cell < 0) return;
    double nearest = std::numeric_limits<double>::infinity();
    for (const CellPlane& plane : surface.planes(static_cast<std::uint32_t>(cell))) {
      const double d = std::abs(plane.normal.dot(p) - plane.offset);
      if (d < nearest) {
        nearest = d;
        normals[i] = plane.normal;
      }
    }
  });
  return normals;
}

}  // namespace dg
