#pragma once
// Basic value types shared by every dockgrammar stage.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <limits>

namespace dg {

using Vec3 = Eigen::Vector3d;
using Vec2 = Eigen::Vector2d;
using Mat3 = Eigen::Matrix3d;
using Mat4 = Eigen::Matrix4d;

/// Indices of a triangle's three corners into a position array (counter-clockwise = front).
using Triangle = std::array<std::uint32_t, 3>;

/// Axis-aligned box in model units; empty() until a point is added.
struct BoundingBox {
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());

  /// Grows the box to contain p.
  void add(const Vec3& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  /// True when no point was added.
  bool empty() const { return !(min.x() <= max.x()); }
  /// Edge lengths (zero vector when empty).
  Vec3 size() const { return empty() ? Vec3::Zero() : Vec3(max - min); }
  /// Longest edge length in model units.
  double longest_side() const { return size().maxCoeff(); }
  /// Length of the diagonal in model units.
  double diagonal() const { return size().norm(); }
  /// Corner `index` (0 .. 7): bits 0, 1, 2 pick the largest x, y, z.
  Vec3 corner(int index) const {
    return {(index & 1) ? max.x() : min.x(), (index & 2) ? max.y() : min.y(), (index & 4) ? max.z() : min.z()};
  }
  /// The box moved by `shift` (model units).
  BoundingBox shifted(const Vec3& shift) const { return {min + shift, max + shift}; }
};

/// Whether boxes a and b lie less than `distance` (model units) apart along every axis: a grown
/// by `distance` overlaps b's interior.
inline bool boxes_within(const BoundingBox& a, const BoundingBox& b, double distance) {
  const Vec3 grow = Vec3::Constant(distance);
  return (a.min.array() < (b.max + grow).array()).all() && (b.min.array() < (a.max + grow).array()).all();
}

}  // namespace dg
