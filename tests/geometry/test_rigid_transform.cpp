#include "geometry/rigid_transform.h"

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <numbers>

using dg::Vec3;

TEST_CASE("rigid motions: powers repeat the motion and negative powers its inverse", "[geometry]") {
  // A screw: 30 degrees about a vertical axis through (1, 2, 0), rising 0.5 per step.
  dg::RigidTransform step;
  step.rotation = Eigen::AngleAxisd(std::numbers::pi / 6.0, Vec3::UnitZ()).toRotationMatrix();
  const Vec3 centre(1.0, 2.0, 0.0);
  step.translation = centre - step.rotation * centre + Vec3(0.0, 0.0, 0.5);
  const Vec3 p(3.0, -1.0, 2.0);

  CHECK((dg::power(step, 0).apply(p) - p).norm() < 1e-12);
  CHECK((dg::power(step, 3).apply(p) - step.apply(step.apply(step.apply(p)))).norm() < 1e-12);
  CHECK((dg::power(step, -2).apply(dg::power(step, 2).apply(p)) - p).norm() < 1e-12);
  // Twelve steps turn once around the axis and rise 6.
  CHECK((dg::power(step, 12).apply(p) - (p + Vec3(0.0, 0.0, 6.0))).norm() < 1e-9);
  CHECK((dg::power(step, -12).apply(p) - (p - Vec3(0.0, 0.0, 6.0))).norm() < 1e-9);
}
