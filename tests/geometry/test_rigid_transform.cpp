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

TEST_CASE("rigid motions: angles of a few nanoradians are measured, and such motions decompose as their translation",
          "[geometry]") {
  // A refined pitch often carries such a rotation: acos of the trace cannot resolve it (it read 0
  // or 1.5e-8 radians), which made the screw axis and the motion's real powers wrong.
  for (double radians : {3e-9, 2e-8, 1e-4}) {
    dg::RigidTransform tilted;
    tilted.rotation = Eigen::AngleAxisd(radians, Vec3(0.6, 0.0, 0.8)).toRotationMatrix();
    tilted.translation = Vec3(0.0, 0.0, 54.0);
    INFO("angle " << radians);
    CHECK(tilted.angle() == Approx(radians).epsilon(1e-6));
    const dg::ScrewParameters screw = dg::screw_parameters(tilted);
    // The screw reproduces the motion at a point 100 units away.
    const Vec3 p(100.0, 0.0, 0.0);
    const Vec3 moved = Eigen::AngleAxisd(screw.angle, screw.axis) * (p - screw.axis_point) + screw.axis_point + screw.slide * screw.axis;
    CHECK((moved - tilted.apply(p)).norm() < 1e-5);
  }
  dg::RigidTransform nearly;
  nearly.rotation = Eigen::AngleAxisd(3e-10, Vec3(0.6, 0.0, 0.8)).toRotationMatrix();
  nearly.translation = Vec3(0.0, 0.0, 54.0);
  const dg::ScrewParameters screw = dg::screw_parameters(nearly);
  CHECK(screw.angle == 0.0);
  CHECK(screw.slide == Approx(54.0));
  CHECK((screw.axis - Vec3::UnitZ()).norm() < 1e-12);
  // Half turns keep their angle.
  dg::RigidTransform half;
  half.rotation = Eigen::AngleAxisd(std::numbers::pi - 1e-9, Vec3::UnitY()).toRotationMatrix();
  CHECK(half.angle() == Approx(std::numbers::pi - 1e-9).epsilon(1e-12));
}
