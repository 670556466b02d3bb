#include "synthesis/r_similarity_match.h"

#include <Eigen/Cholesky>

#include <cmath>

namespace dg {

bool neighbourhoods_match(const SurfaceIndex& candidate, const SurfaceIndex& exemplar, const SurfacePoint& y,
                          std::span<const std::uint32_t> ball, const RigidTransform& t, const MatchTolerances& tolerances,
                          std::vector<std::uint32_t>& scratch) {
  if (ball.empty()) return false;
  auto allowed = [&](std::size_t samples) {
    return static_cast<std::size_t>(std::floor(tolerances.max_missing_fraction * static_cast<double>(samples)));
  };
  std::size_t missing = 0, may_miss = allowed(ball.size());
  for (std::uint32_t i : ball) {
    const SurfacePoint& p = candidate.samples()[i];
    if (!exemplar.touches(t.apply(p.position), t.apply_direction(p.normal), tolerances.tolerance, tolerances.min_cos) &&
        ++missing > may_miss)
      return false;
  }
  const RigidTransform back = t.inverse();
  if (!exemplar.gather_connected(t.apply(y.position), t.apply_direction(y.normal), tolerances.r, tolerances.tolerance,
                                 tolerances.min_cos, scratch))
    return false;
  missing = 0;
  may_miss = allowed(scratch.size());
  for (std::uint32_t i : scratch) {
    const SurfacePoint& q = exemplar.samples()[i];
    if (!candidate.touches(back.apply(q.position), back.apply_direction(q.normal), tolerances.tolerance,
                           tolerances.min_cos) &&
        ++missing > may_miss)
      return false;
  }
  return true;
}

RigidTransform refine_alignment(const SurfaceIndex& candidate, const SurfaceIndex& exemplar, const Vec3& y,
                                std::span<const std::uint32_t> ball, RigidTransform t, const MatchTolerances& tolerances) {
  using Mat6 = Eigen::Matrix<double, 6, 6>;
  using Vec6 = Eigen::Matrix<double, 6, 1>;
  const double r2 = tolerances.r * tolerances.r;
  for (int iteration = 0; iteration < tolerances.icp_iterations; ++iteration) {
    const Vec3 pivot = t.apply(y);
    Mat6 normal_matrix = Mat6::Zero();
    Vec6 rhs = Vec6::Zero();
    std::size_t pairs = 0;
    for (std::uint32_t i : ball) {
      const SurfacePoint& p = candidate.samples()[i];
      const Vec3 q = t.apply(p.position);
      const auto target = exemplar.closest(q, t.apply_direction(p.normal), tolerances.icp_cutoff, 0.5);
      if (!target) continue;
      // Residual along the target normal after a small rotation w about the pivot and a shift d:
      // ((q - c) + w x (q - pivot) + d) . n  =  res + ((q - pivot) x n) . w + n . d
      Vec6 row;
      row.head<3>() = (q - pivot).cross(target->normal);
      row.tail<3>() = target->normal;
      normal_matrix += row * row.transpose();
      rhs -= row * (q - target->position).dot(target->normal);
      ++pairs;
    }
    if (pairs < 6) break;
    // A small damping keeps the free directions (slides) where they are.
    const double damping = 1e-9 * static_cast<double>(pairs);
    for (int k = 0; k < 3; ++k) normal_matrix(k, k) += damping * r2;
    for (int k = 3; k < 6; ++k) normal_matrix(k, k) += damping;
    const Vec6 step = normal_matrix.ldlt().solve(rhs);
    if (!step.allFinite()) break;
    const Vec3 w = step.head<3>(), d = step.tail<3>();
    const double angle = w.norm();
    const Mat3 rotation = angle > 0.0 ? Mat3(Eigen::AngleAxisd(angle, w / angle)) : Mat3::Identity();
    RigidTransform update;
    update.rotation = rotation;
    update.translation = pivot - rotation * pivot + d;
    t = update.after(t);
    if (d.norm() + angle * tolerances.r < 1e-9 * tolerances.r) break;
  }
  return t;
}

}  // namespace dg
