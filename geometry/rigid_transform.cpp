#include "geometry/rigid_transform.h"

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>

namespace dg {

RigidTransform RigidTransform::inverse() const {
  RigidTransform inv;
  inv.rotation = rotation.transpose();
  inv.translation = -(inv.rotation * translation);
  return inv;
}

RigidTransform RigidTransform::after(const RigidTransform& first) const {
  return {rotation * first.rotation, rotation * first.translation + translation};
}

RigidTransform shifted_motion(const RigidTransform& t, const Vec3& origin) {
  return {t.rotation, t.translation + origin - t.rotation * origin};
}

RigidTransform power(const RigidTransform& t, int k) {
  const RigidTransform step = k >= 0 ? t : t.inverse();
  RigidTransform result;
  for (int j = 0; j < std::abs(k); ++j) result = step.after(result);
  return result;
}

Mat4 RigidTransform::matrix() const {
  Mat4 m = Mat4::Identity();
  m.topLeftCorner<3, 3>() = rotation;
  m.topRightCorner<3, 1>() = translation;
  return m;
}

double RigidTransform::angle() const {
  // sin from the antisymmetric part, cos from the trace: unlike acos of the trace alone, exact for
  // angles below 1e-8 (acos cannot resolve 1 - angle^2 / 2 there).
  const Vec3 twice_sine_axis(rotation(2, 1) - rotation(1, 2), rotation(0, 2) - rotation(2, 0), rotation(1, 0) - rotation(0, 1));
  return std::atan2(0.5 * twice_sine_axis.norm(), std::clamp((rotation.trace() - 1.0) / 2.0, -1.0, 1.0));
}

Vec3 RigidTransform::axis() const {
  const Eigen::AngleAxisd angle_axis(rotation);
  if (angle_axis.angle() < 1e-12) return translation.norm() > 0.0 ? Vec3(translation.normalized()) : Vec3::UnitZ();
  return angle_axis.axis();
}

ScrewParameters screw_parameters(const RigidTransform& transform) {
  ScrewParameters screw;
  screw.angle = transform.angle();
  screw.axis = transform.axis();
  // Below 1e-9 radians the axis point, about |t| / angle away, loses the translation to rounding
  // (1e-16 of that distance): such a motion is taken as its translation.
  if (screw.angle < 1e-9) {
    screw.angle = 0.0;
    screw.slide = transform.translation.norm();
    screw.axis = screw.slide > 0.0 ? Vec3(transform.translation / screw.slide) : Vec3::UnitZ();
    return screw;
  }
  screw.slide = screw.axis.dot(transform.translation);
  // The axis point p solves (I - R) p = t_perp within the plane orthogonal to the axis.
  const Vec3 perpendicular = transform.translation - screw.slide * screw.axis;
  const Mat3 system = Mat3::Identity() - transform.rotation;
  const Eigen::JacobiSVD<Mat3> svd(system, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Vec3 singular = svd.singularValues();
  for (int i = 0; i < 3; ++i) singular[i] = singular[i] > 1e-12 ? 1.0 / singular[i] : 0.0;
  screw.axis_point = svd.matrixV() * singular.asDiagonal() * svd.matrixU().transpose() * perpendicular;
  return screw;
}

std::string motion_kind(const RigidTransform& transform, double angle_tolerance, double slide_tolerance) {
  if (transform.angle() < angle_tolerance) return "translation";
  return std::abs(screw_parameters(transform).slide) < slide_tolerance ? "rotation" : "screw";
}

RigidTransform fit_rigid_transform(const std::vector<Vec3>& from, const std::vector<Vec3>& to) {
  RigidTransform result;
  if (from.empty() || from.size() != to.size()) return result;
  Vec3 centre_from = Vec3::Zero(), centre_to = Vec3::Zero();
  for (std::size_t i = 0; i < from.size(); ++i) {
    centre_from += from[i];
    centre_to += to[i];
  }
  centre_from /= static_cast<double>(from.size());
  centre_to /= static_cast<double>(to.size());
  Mat3 covariance = Mat3::Zero();
  for (std::size_t i = 0; i < from.size(); ++i) covariance += (to[i] - centre_to) * (from[i] - centre_from).transpose();
  const Eigen::JacobiSVD<Mat3> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 correction = Mat3::Identity();
  if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0) correction(2, 2) = -1.0;
  result.rotation = svd.matrixU() * correction * svd.matrixV().transpose();
  result.translation = centre_to - result.rotation * centre_from;
  return result;
}

bool same_motion(const RigidTransform& a, const RigidTransform& b, const Vec3& point, double distance, double angle) {
  return (a.apply(point) - b.apply(point)).norm() < distance &&
         RigidTransform{a.rotation.transpose() * b.rotation, Vec3::Zero()}.angle() < angle;
}

RigidTransform rigid_from_matrix(const Mat4& matrix) {
  const Mat3 linear = matrix.topLeftCorner<3, 3>();
  const Eigen::JacobiSVD<Mat3> svd(linear, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 correction = Mat3::Identity();
  if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0) correction(2, 2) = -1.0;
  return {svd.matrixU() * correction * svd.matrixV().transpose(), matrix.topRightCorner<3, 1>()};
}

double largest_corner_move(const RigidTransform& transform, const BoundingBox& box) {
  double largest = 0.0;
  for (int corner = 0; corner < 8; ++corner) largest = std::max(largest, (transform.apply(box.corner(corner)) - box.corner(corner)).norm());
  return largest;
}

}  // namespace dg
