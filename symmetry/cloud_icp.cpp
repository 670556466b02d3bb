#include "symmetry/cloud_icp.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <numbers>

namespace dg {
namespace {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

// The plane of `cell` nearest to p within `cutoff` whose normal agrees with `normal` up to sign
// (cosine above `cos_angle`), or null.
const CellPlane* nearest_plane(const VoxelSurface& surface, std::int64_t cell, const Vec3& p, const Vec3* normal, double cutoff,
                               double cos_angle) {
  if (cell < 0) return nullptr;
  const CellPlane* best = nullptr;
  double best_distance = cutoff;
  for (const CellPlane& plane : surface.planes(static_cast<std::uint32_t>(cell))) {
    if (normal && std::abs(plane.normal.dot(*normal)) < cos_angle) continue;
    const double d = std::abs(plane.normal.dot(p) - plane.offset);
    if (d < best_distance) {
      best_distance = d;
      best = &plane;
    }
  }
  return best;
}

}  // namespace

RigidTransform refine_on_points(const PointCloud& cloud, const VoxelSurface& surface, const RigidTransform& t,
                                const CloudIcpOptions& options) {
  const double eps = surface.eps();
  const double cos_angle = std::cos(options.max_angle_degrees * std::numbers::pi / 180.0);
  const std::size_t stride = std::max<std::size_t>(1, (cloud.positions.size() + options.max_samples - 1) / options.max_samples);
  // Samples with their own plane normal (fixed: they do not depend on t).
  std::vector<std::pair<Vec3, Vec3>> samples;
  for (std::size_t p = 0; p < cloud.positions.size(); p += stride) {
    const Vec3& x = cloud.positions[p];
    const CellPlane* own = nearest_plane(surface, surface.find(surface.voxel_of(x)), x, nullptr, 0.3 * eps, 0.0);
    if (own) samples.emplace_back(x, own->normal);
  }
  RigidTransform current = t;
  for (double cutoff_eps : options.cutoffs_eps) {
    // Linearized about the pairs' centroid o: y -> y + w x (y - o) + v.
    std::vector<std::pair<Vec3, const CellPlane*>> pairs;
    Vec3 centroid = Vec3::Zero();
    for (const auto& [x, n] : samples) {
      const Vec3 y = current.apply(x);
      const Vec3 mapped_normal = current.apply_direction(n);
      const CellPlane* target =
          nearest_plane(surface, surface.find(surface.voxel_of(y)), y, &mapped_normal, cutoff_eps * eps, cos_angle);
      if (!target) continue;
      pairs.emplace_back(y, target);
      centroid += y;
    }
    if (pairs.size() < 6) return t;
    centroid /= static_cast<double>(pairs.size());
    Mat6 normal_matrix = Mat6::Zero();
    Vec6 right = Vec6::Zero();
    for (const auto& [y, plane] : pairs) {
      Vec6 row;
      row << (y - centroid).cross(plane->normal), plane->normal;
      normal_matrix += row * row.transpose();
      right -= row * (plane->normal.dot(y) - plane->offset);
    }
    // Pseudo-inverse: directions with tiny eigenvalues (slides the pairs allow) stay put.
    const Eigen::SelfAdjointEigenSolver<Mat6> solver(normal_matrix);
    const double largest = solver.eigenvalues().maxCoeff();
    if (!(largest > 0.0)) return t;
    Vec6 step = Vec6::Zero();
    for (int k = 0; k < 6; ++k)
      if (solver.eigenvalues()(k) > 1e-6 * largest)
        step += solver.eigenvectors().col(k) * (solver.eigenvectors().col(k).dot(right) / solver.eigenvalues()(k));
    const Vec3 w = step.head<3>();
    RigidTransform delta;
    if (w.norm() > 0.0) delta.rotation = Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix();
    delta.translation = centroid - delta.rotation * centroid + step.tail<3>();
    current = delta.after(current);
  }
  return current;
}

}  // namespace dg
