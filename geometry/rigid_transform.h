#pragma once
// Proper rigid motions x -> R x + t (rotation R with det +1, translation t in model units).

#include "geometry/types.h"

#include <string>
#include <vector>

namespace dg {

struct RigidTransform {
  Mat3 rotation = Mat3::Identity();
  Vec3 translation = Vec3::Zero();

  /// Image of a point.
  Vec3 apply(const Vec3& p) const { return rotation * p + translation; }
  /// Image of a direction (rotation only).
  Vec3 apply_direction(const Vec3& d) const { return rotation * d; }
  /// The inverse motion.
  RigidTransform inverse() const;
  /// This motion after `first`: x -> this(first(x)).
  RigidTransform after(const RigidTransform& first) const;
  /// 4x4 homogeneous matrix (row-major when read row by row).
  Mat4 matrix() const;
  /// Rotation angle in radians, in [0, pi].
  double angle() const;
  /// Unit rotation axis (any unit vector when the angle is 0).
  Vec3 axis() const;
};

/// The motion `t`, given in a frame whose origin lies at `origin`, in the coordinates that frame
/// was moved from: x -> t(x - origin) + origin (translations stay as they are).
RigidTransform shifted_motion(const RigidTransform& t, const Vec3& origin);

/// The motion applied k times (k < 0: its inverse applied -k times; k = 0: the identity).
RigidTransform power(const RigidTransform& t, int k);

/// Identity-free description of a motion, as a screw: rotation by `angle` about the line
/// through `axis_point` with direction `axis`, then translation by `slide` along the axis.
/// Translations have angle 0, axis = translation direction and slide = its length.
struct ScrewParameters {
  double angle = 0.0;  ///< radians, [0, pi]
  Vec3 axis = Vec3::UnitZ();
  Vec3 axis_point = Vec3::Zero();
  double slide = 0.0;  ///< model units along `axis`
};

/// Screw decomposition of a rigid motion (Chasles' theorem).
ScrewParameters screw_parameters(const RigidTransform& transform);

/// Kind of motion: "translation" (angle below angle_tolerance radians), "rotation" (slide along
/// the axis below slide_tolerance model units) or "screw".
std::string motion_kind(const RigidTransform& transform, double angle_tolerance, double slide_tolerance);

/// The rigid motion that best maps points `from` onto `to` in the least-squares sense (Kabsch,
/// reflections excluded). Needs at least three non-collinear pairs for a unique answer; with
/// fewer the result is still a proper motion that fits them.
RigidTransform fit_rigid_transform(const std::vector<Vec3>& from, const std::vector<Vec3>& to);

/// True when a and b move `point` to within `distance` (model units) of each other and their
/// rotations differ by less than `angle` radians (default about half a degree).
bool same_motion(const RigidTransform& a, const RigidTransform& b, const Vec3& point, double distance, double angle = 0.01);

/// How far `transform` moves the corner of `box` it moves farthest (model units).
double largest_corner_move(const RigidTransform& transform, const BoundingBox& box);

/// Rigid motion from a 4x4 matrix (the upper-left 3x3 is re-orthonormalized).
RigidTransform rigid_from_matrix(const Mat4& matrix);

}  // namespace dg
