#include "grammar/seam_curve.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <optional>

namespace {

// Three flat fins on the edge from (0, 0, 0) to (0, 0, 1): triangle 0 reaches out along +x,
// triangle 1 along +y, triangle 2 along -x. Triangle 3 continues fin 0 beyond x = 1.
dg::TriangleMesh fins_on_one_edge() {
  dg::TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 1}};
  mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {2, 1, 5}};
  return mesh;
}

}  // namespace

TEST_CASE("seam curve: an edge that three triangles share is a seam where the piece meets any of the others",
          "[grammar][seam_curve]") {
  // Real assets have such edges (the Blendswap radiator's fins: 2,873 of them). The fins' edge
  // was no seam at all when only two-triangle edges counted, so a docker could leave a part
  // behind at one location and not at another with the same seam curve.
  const dg::TriangleMesh mesh = fins_on_one_edge();
  const dg::EdgeUsers users = dg::edge_users(mesh);

  // Fin 0 alone: the shared edge (fins 1 and 2 stay outside) and its edge to triangle 3.
  std::vector<char> inside{1, 0, 0, 0};
  std::vector<dg::Segment> seam = dg::seam_segments(mesh, users, {0}, inside);
  REQUIRE(seam.size() == 2);
  auto is_edge = [](const dg::Segment& s, const dg::Vec3& a, const dg::Vec3& b) {
    return (s[0] == a && s[1] == b) || (s[0] == b && s[1] == a);
  };
  CHECK((is_edge(seam[0], {0, 0, 0}, {0, 0, 1}) || is_edge(seam[1], {0, 0, 0}, {0, 0, 1})));
  CHECK((is_edge(seam[0], {1, 0, 0}, {0, 0, 1}) || is_edge(seam[1], {1, 0, 0}, {0, 0, 1})));

  // Fins 0 and 1 with triangle 3: fin 2 is still outside, so the shared edge stays a seam, once
  // for each inside triangle on it.
  inside = {1, 1, 0, 1};
  seam = dg::seam_segments(mesh, users, {0, 1, 3}, inside);
  CHECK(seam.size() == 2);
  for (const dg::Segment& s : seam) CHECK(is_edge(s, {0, 0, 0}, {0, 0, 1}));

  // Every triangle inside: no seam; the open border of the fins is the model's own.
  inside = {1, 1, 1, 1};
  CHECK(dg::seam_segments(mesh, users, {0, 1, 2, 3}, inside).empty());
}

TEST_CASE("seam curve alignment: a curve moved a little is carried back onto the other, one moved too far is not",
          "[grammar][seam_curve]") {
  // An octagon of radius 1 in the plane z = 2 and a copy moved by 0.04 along x and turned by
  // 0.5 degree about z: alignment finds the motion back within 1e-6; a copy moved 0.3 away, with
  // a reach of 0.1, has points no closer than the reach and gets nothing.
  std::vector<dg::Segment> octagon;
  for (int k = 0; k < 8; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 8, b = 2.0 * std::numbers::pi * (k + 1) / 8;
    octagon.push_back({dg::Vec3(std::cos(a), std::sin(a), 2.0), dg::Vec3(std::cos(b), std::sin(b), 2.0)});
  }
  dg::RigidTransform motion;
  motion.rotation = Eigen::AngleAxisd(0.5 * std::numbers::pi / 180.0, dg::Vec3::UnitZ()).toRotationMatrix();
  motion.translation = dg::Vec3(0.04, 0.0, 0.0);
  auto moved_by = [&](const dg::RigidTransform& t) {
    std::vector<dg::Segment> moved = octagon;
    for (dg::Segment& s : moved) s = {t.apply(s[0]), t.apply(s[1])};
    return moved;
  };
  const std::vector<dg::Segment> moved = moved_by(motion);
  CHECK(dg::curve_length(moved) == Approx(16.0 * std::sin(std::numbers::pi / 8)));  // 8 sides of 2 sin(pi / 8)
  CHECK(dg::seam_misfit(moved, octagon, 0.1, 0.1) > 0.01);
  const std::optional<dg::RigidTransform> back = dg::align_seam_curve(moved, octagon, 0.1, 0.1);
  REQUIRE(back.has_value());
  const dg::RigidTransform round_trip = back->after(motion);
  CHECK(round_trip.angle() < 1e-6);
  CHECK(round_trip.translation.norm() < 1e-6);
  std::vector<dg::Segment> aligned = moved;
  for (dg::Segment& s : aligned) s = {back->apply(s[0]), back->apply(s[1])};
  CHECK(dg::seam_misfit(aligned, octagon, 0.1, 0.1) < 1e-6);

  dg::RigidTransform far;
  far.translation = dg::Vec3(0.3, 0.0, 0.0);
  CHECK_FALSE(dg::align_seam_curve(moved_by(far), octagon, 0.1, 0.1).has_value());
}
