#include "symmetry/slippage.h"

#include <Eigen/Eigenvalues>

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

}  // namespace dg
