#include "symmetry/slippage.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

namespace dg {

SlippageResult slippage(const std::vector<Vec3>& points, const std::vector<Vec3>& normals, double threshold) {
  SlippageResult result;
  const std::size_t n = std::min(points.size(), normals.size());
  if (n == 0) {
    for (int k = 0; k < 6; ++k) {
      SlippableMotion motion;
      (k < 3 ? motion.rotation : motion.translation)[k % 3] = 1.0;
      result.motions.push_back(motion);
    }
    return result;
  }
  Vec3 centre = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) centre += points[i];
  centre /= static_cast<double>(n);
  double radius = 0.0;
  for (std::size_t i = 0; i < n; ++i) radius += (points[i] - centre).norm();
  radius = radius > 0.0 ? radius / static_cast<double>(n) : 1.0;

  Eigen::Matrix<double, 6, 6> matrix = Eigen::Matrix<double, 6, 6>::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 p = (points[i] - centre) / radius;
    Eigen::Matrix<double, 6, 1> row;
    row << p.cross(normals[i]), normals[i];
    matrix += row * row.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> solver(matrix);
  const double largest = solver.eigenvalues()[5];
  for (int k = 0; k < 6; ++k) {
    const double ratio = largest > 0.0 ? solver.eigenvalues()[k] / largest : 0.0;
    if (ratio >= threshold) break;
    SlippableMotion motion;
    motion.rotation = solver.eigenvectors().col(k).head<3>();
    // Back to model units: a rotation about the centroid, translation scaled by the radius.
    motion.translation = radius * solver.eigenvectors().col(k).tail<3>() - motion.rotation.cross(centre);
    motion.eigenvalue_ratio = ratio;
    result.motions.push_back(motion);
  }
  return result;
}

std::size_t joint_slippage_dimension(const std::vector<OrientedPoints>& parts, double threshold) {
  // Motions as velocity fields v(p) = w x p + t, written about the centroid C of all points with
  // the translation divided by their mean radius L: u = (w, (t + w x C) / L). The motions shared
  // by all parts are the null space of the sum of the projectors onto each part's complement.
  Vec3 centre = Vec3::Zero();
  std::size_t count = 0;
  for (const OrientedPoints& part : parts) {
    for (const Vec3& p : part.points) centre += p;
    count += part.points.size();
  }
  if (count == 0) return 6;
  centre /= static_cast<double>(count);
  double scale = 0.0;
  for (const OrientedPoints& part : parts)
    for (const Vec3& p : part.points) scale += (p - centre).norm();
  scale = scale > 0.0 ? scale / static_cast<double>(count) : 1.0;

  using Matrix6 = Eigen::Matrix<double, 6, 6>;
  Matrix6 outside_sum = Matrix6::Zero();
  for (const OrientedPoints& part : parts) {
    if (part.points.size() < 6) continue;
    const SlippageResult own = slippage(part.points, part.normals, threshold);
    Eigen::Matrix<double, 6, Eigen::Dynamic> basis(6, own.motions.size());
    for (std::size_t k = 0; k < own.motions.size(); ++k) {
      const SlippableMotion& m = own.motions[k];
      basis.col(static_cast<Eigen::Index>(k)) << m.rotation, (m.translation + m.rotation.cross(centre)) / scale;
    }
    // Orthonormal basis of the part's slippable motions, then the projector onto the rest.
    const Eigen::HouseholderQR<Eigen::Matrix<double, 6, Eigen::Dynamic>> qr(basis);
    const Eigen::Matrix<double, 6, Eigen::Dynamic> q =
        (qr.householderQ() * Matrix6::Identity()).leftCols(static_cast<Eigen::Index>(own.motions.size()));
    outside_sum += Matrix6::Identity() - q * q.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Matrix6> solver(outside_sum);
  std::size_t shared = 0;
  // A motion within about 2 degrees of every part's slippable motions slides them all.
  for (int k = 0; k < 6; ++k) shared += solver.eigenvalues()[k] < threshold ? 1 : 0;
  return shared;
}

}  // namespace dg
