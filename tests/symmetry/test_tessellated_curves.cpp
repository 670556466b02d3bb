// Curves tessellated in steps that a symmetry does not share: a helical handrail swept in
// 8-degree segments under the 22.5-degree screw of the stairs it follows. The mapped facets land
// on the curve but tilted against its facets, so exact plane matching rejects the whole rail.

#include "geometry/prepared_model.h"
#include "geometry/tessellation_bend.h"
#include "symmetry/symmetric_region.h"

#include "support/cell_symmetry.h"
#include "support/shapes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

using dg::Vec3;

namespace {

constexpr double kScrewDegrees = 22.5;
constexpr double kScrewRise = 0.2;
constexpr double kHelixRadius = 0.7;
constexpr double kTubeRadius = 0.05;

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// A tube of pentagonal section along the helix about +y that rises kScrewRise per kScrewDegrees,
// in rings every `segment_degrees` over `turns` turns (open ends).
dg::TriangleMesh helical_tube(double segment_degrees, double turns) {
  dg::TriangleMesh mesh;
  const int rings = static_cast<int>(std::lround(turns * 360.0 / segment_degrees)) + 1;
  const double rise_per_radian = kScrewRise / radians(kScrewDegrees);
  for (int k = 0; k < rings; ++k) {
    const double theta = radians(k * segment_degrees);
    const Vec3 outward(std::cos(theta), 0, std::sin(theta));
    const Vec3 centre = kHelixRadius * outward + Vec3(0, rise_per_radian * theta, 0);
    for (int j = 0; j < 5; ++j) {
      const double phi = 2 * std::numbers::pi * j / 5;
      mesh.positions.push_back(centre + kTubeRadius * (std::cos(phi) * outward + std::sin(phi) * Vec3::UnitY()));
    }
  }
  for (int k = 0; k + 1 < rings; ++k)
    for (int j = 0; j < 5; ++j) {
      const auto at = [&](int ring, int corner) { return static_cast<std::uint32_t>(5 * ring + corner % 5); };
      mesh.triangles.push_back({at(k, j), at(k + 1, j), at(k + 1, j + 1)});
      mesh.triangles.push_back({at(k, j), at(k + 1, j + 1), at(k, j + 1)});
    }
  return mesh;
}

// The screw that moves the helix along itself by kScrewDegrees.
dg::RigidTransform stair_screw() {
  const Eigen::AngleAxisd turn(-radians(kScrewDegrees), Vec3::UnitY());  // +theta in the x-z plane
  return {turn.toRotationMatrix(), Vec3(0, kScrewRise, 0)};
}

dg::PreparedModel prepared_mesh(dg::TriangleMesh mesh) {
  dg::Model model;
  model.mesh = std::move(mesh);
  return dg::prepare_model(std::move(model));
}

}  // namespace

TEST_CASE("tessellation bend: facets and feature polylines of a curve turn by its step, flat ones by 0", "[geometry]") {
  const dg::TriangleMesh tube = helical_tube(8.0, 1.0);
  const std::vector<dg::FeatureEdge> features = dg::find_feature_edges(tube, dg::kDefaultSharpAngleDegrees);
  // Rings are 8 degrees apart about the axis, so no facet or rail edge turns by more from its
  // neighbour (split quads and the rail's slope turn by less); the pentagon's 72-degree edges are
  // features, and their polylines along the rail are not corners.
  const std::vector<double> bends = dg::triangle_bend_degrees(tube, features);
  CHECK(*std::max_element(bends.begin(), bends.end()) <= 8.0 + 1e-9);
  CHECK(std::count_if(bends.begin(), bends.end(), [](double bend) { return bend > 1.0; }) >= 0.95 * bends.size());
  const std::vector<double> edge_bends = dg::feature_edge_bend_degrees(tube, features, dg::kDefaultCornerAngleDegrees);
  CHECK(*std::max_element(edge_bends.begin(), edge_bends.end()) <= 8.0 + 1e-9);
  const auto along_rail = std::count_if(edge_bends.begin(), edge_bends.end(), [](double bend) { return bend > 1.0; });
  CHECK(along_rail >= 5 * 40);  // the five pentagon corners run along the rail's 45 segments

  const dg::TriangleMesh box = dg::test::make_box(Vec3::Zero(), Vec3(1, 2, 3));
  const std::vector<dg::FeatureEdge> box_features = dg::find_feature_edges(box, dg::kDefaultSharpAngleDegrees);
  for (double bend : dg::triangle_bend_degrees(box, box_features)) CHECK(bend == 0.0);
  for (double bend : dg::feature_edge_bend_degrees(box, box_features, dg::kDefaultCornerAngleDegrees)) CHECK(bend == 0.0);
}

TEST_CASE("handrail in 8-degree segments: the stairs' 22.5-degree screw maps it onto itself", "[symmetry]") {
  const dg::PreparedModel prepared = prepared_mesh(helical_tube(8.0, 1.5));
  const dg::RigidTransform screw = stair_screw();
  // Facets of a tessellated curve may land tilted by up to their step: all but the end that
  // slides off (22.5 of 540 degrees) and the cells next to it.
  const double tolerant = dg::test::symmetric_fraction(prepared, screw, dg::RegionOptions{});
  CHECK(tolerant > 0.85);
  // Exact matching only (no tilt for facets of curves) rejects almost the whole rail.
  dg::RegionOptions exact;
  exact.max_bend_degrees = 0.0;
  CHECK(dg::test::symmetric_fraction(prepared, screw, exact) < 0.3);
  // A rail tessellated in the screw's own step matches exactly, as before.
  const dg::PreparedModel shared_step = prepared_mesh(helical_tube(22.5 / 3, 1.5));
  CHECK(dg::test::symmetric_fraction(shared_step, screw, exact) > 0.85);
}

TEST_CASE("handrail in 8-degree segments: a screw with the wrong rise is still rejected", "[symmetry]") {
  // The tilt allowance covers facets landing on the curve, not a curve moved off itself: a rise
  // one voxel too high moves the rail off itself by 0.8 voxels (its slope is 36 degrees).
  const dg::PreparedModel prepared = prepared_mesh(helical_tube(8.0, 1.5));
  dg::RigidTransform off = stair_screw();
  off.translation.y() += prepared.surface.eps();
  CHECK(dg::test::symmetric_fraction(prepared, off, dg::RegionOptions{}) < 0.2);
}
