// A model's up axis read off its symmetries: the coordinate axis of its dominant turn.

#include "symmetry/turn_axis.h"

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <numbers>

namespace {

// A family of one member: `kind` turning by `degrees` about `axis`, mapping `fraction` of the
// surface onto itself.
void add_family(dg::SymmetryResult& result, const char* kind, double degrees, const dg::Vec3& axis, double fraction) {
  dg::RigidTransform motion;
  motion.rotation = Eigen::AngleAxisd(degrees * std::numbers::pi / 180.0, axis.normalized()).toRotationMatrix();
  if (std::string(kind) == "screw") motion.translation = 0.3 * axis.normalized();
  dg::DetectedSymmetry symmetry;
  symmetry.transform = motion;
  symmetry.kind = kind;
  symmetry.symmetric_fraction = fraction;
  symmetry.family = result.families.size();
  result.symmetries.push_back(symmetry);
  dg::SymmetryFamily family;
  family.generator = motion;
  family.kind = kind;
  family.members = {result.symmetries.size() - 1};
  family.powers = {1};
  family.count = 1;
  result.families.push_back(family);
}

}  // namespace

TEST_CASE("turn axis: the largest turn of a third of a turn or less about a coordinate axis gives up", "[symmetry]") {
  dg::SymmetryResult result;
  add_family(result, "translation", 0.0, dg::Vec3::UnitX(), 0.95);             // 0: no turn
  add_family(result, "rotation", 180.0, dg::Vec3::UnitX(), 0.9);               // 1: a flip says nothing about up
  add_family(result, "rotation", 45.0, dg::Vec3(1, 1, 0), 0.8);                // 2: about no coordinate axis
  add_family(result, "rotation", 60.0, dg::Vec3::UnitZ(), 0.6);                // 3: the table's six chairs
  add_family(result, "rotation", 90.0, dg::Vec3::UnitY(), 0.3);                // 4: too small a share
  add_family(result, "rotation", 90.0, dg::Vec3::UnitZ(), 0.55);               // 5: a smaller turn about z
  const std::optional<dg::TurnAxis> turn = dg::coordinate_turn_axis(result);
  REQUIRE(turn);
  CHECK(turn->axis == 2);
  CHECK(turn->family == 3);
  CHECK(turn->fraction == Approx(0.6));

  // Below the share nothing is read off.
  CHECK_FALSE(dg::coordinate_turn_axis(result, 0.75));

  // With a turn about a second axis (a screw about -y: the axis's sign does not matter), as a
  // stack of cubes has, up is not read off turns.
  add_family(result, "screw", 30.0, -dg::Vec3::UnitY(), 0.7);
  CHECK_FALSE(dg::coordinate_turn_axis(result));
  dg::SymmetryResult stairs;
  add_family(stairs, "screw", 30.0, -dg::Vec3::UnitY(), 0.7);
  REQUIRE(dg::coordinate_turn_axis(stairs));
  CHECK(dg::coordinate_turn_axis(stairs)->axis == 1);
  // A third of a turn counts, within the detector's angle noise.
  dg::SymmetryResult third;
  add_family(third, "rotation", 120.5, dg::Vec3::UnitX(), 0.55);
  REQUIRE(dg::coordinate_turn_axis(third));
  CHECK(dg::coordinate_turn_axis(third)->axis == 0);
}
