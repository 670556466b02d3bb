// Plane seams through docking-site bands: the least-squares plane of a flat band, and the plane
// that parts a docker from the rest when the band is thick.

#include "grammar/seam_plane.h"

#include "geometry/feature_edges.h"
#include "support/shapes.h"

#include <catch2/catch.hpp>

#include <functional>

namespace {

constexpr double kEps = 0.1;

// Two bars along x, eps 0.1: [0, 10] x [0, 1] x [0, 1] and the same 3 higher in y (each moved by
// 0.03 off the voxel planes).
dg::VoxelSurface two_bars() {
  dg::TriangleMesh mesh = dg::test::make_box(dg::Vec3(0.03, 0.03, 0.03), dg::Vec3(10.03, 1.03, 1.03));
  dg::test::append(mesh, dg::test::make_box(dg::Vec3(0.03, 3.03, 0.03), dg::Vec3(10.03, 4.03, 1.03)));
  dg::VoxelSurfaceOptions options;
  options.r = 4 * kEps;
  options.eps = kEps;
  return dg::build_voxel_surface(mesh, dg::find_feature_edges(mesh), options);
}

// The cells (ascending) whose centre passes `inside`.
std::vector<std::uint32_t> cells_where(const dg::VoxelSurface& surface, const std::function<bool(const dg::Vec3&)>& inside) {
  std::vector<std::uint32_t> cells;
  for (std::uint32_t c = 0; c < surface.cell_count(); ++c)
    if (inside(surface.centre(c))) cells.push_back(c);
  return cells;
}

// A location on the lower bar (or the upper one): band where x lies in [from, to), docker
// beyond `to`.
struct BarLocation {
  std::vector<std::uint32_t> site, docker;
};

BarLocation bar_location(const dg::VoxelSurface& surface, bool lower_bar, double from, double to) {
  auto on_bar = [lower_bar](const dg::Vec3& p) { return lower_bar == (p.y() < 2.0); };
  return {cells_where(surface, [&](const dg::Vec3& p) { return on_bar(p) && p.x() >= from && p.x() < to; }),
          cells_where(surface, [&](const dg::Vec3& p) { return on_bar(p) && p.x() >= to; })};
}

}  // namespace

TEST_CASE("seam plane: a thick band across a bar is not flat, yet a plane parts the docker from the rest",
          "[grammar][seam_plane]") {
  const dg::VoxelSurface surface = two_bars();
  // Band of six voxels across the lower bar (x in [4.5, 5.1)), the docker beyond it.
  const BarLocation thick = bar_location(surface, true, 4.5, 5.1);
  REQUIRE(thick.site.size() > 50);
  CHECK_FALSE(dg::fit_band_plane(surface, thick.site, 2 * kEps));
  const std::vector<dg::SeamLocation> one{{&thick.site, &thick.docker, {}}};
  const std::optional<dg::Plane> plane = dg::plane_between_sides(surface, one, 0.25 * kEps);
  REQUIRE(plane);
  // Across the bar, facing the docker, halfway between the rest's voxels (up to x = 4.5) and
  // the docker's (from x = 5.1).
  CHECK(plane->normal.x() == Approx(1.0).margin(1e-9));
  CHECK(plane->offset == Approx(4.8).margin(1e-9));

  // A band one voxel thick is flat: its least-squares plane runs through the voxel centres.
  const BarLocation thin = bar_location(surface, true, 5.0, 5.1);
  const std::optional<dg::Plane> flat = dg::fit_band_plane(surface, thin.site, 2 * kEps);
  REQUIRE(flat);
  CHECK(std::abs(flat->normal.x()) == Approx(1.0).margin(1e-9));
  CHECK(std::abs(flat->offset) == Approx(5.05).margin(1e-9));
}

TEST_CASE("seam plane: one plane must part the docker at every location, each seen from its own frame",
          "[grammar][seam_plane]") {
  const dg::VoxelSurface surface = two_bars();
  const BarLocation first = bar_location(surface, true, 4.5, 5.1);
  // The same band on the upper bar, 0.2 further along x and 3 higher.
  const BarLocation second = bar_location(surface, false, 4.7, 5.3);
  dg::RigidTransform back;  // the upper location moved onto the first
  back.translation = dg::Vec3(-0.2, -3.0, 0.0);
  const std::vector<dg::SeamLocation> both{{&first.site, &first.docker, {}}, {&second.site, &second.docker, back}};
  const std::optional<dg::Plane> plane = dg::plane_between_sides(surface, both, 0.25 * kEps);
  REQUIRE(plane);
  CHECK(plane->normal.x() == Approx(1.0).margin(1e-9));
  CHECK(plane->offset == Approx(4.8).margin(1e-6));

  // Seen from a frame a voxel off, the second location's voxels reach across the first's gap:
  // no plane parts both.
  dg::RigidTransform off = back;
  off.translation.x() += 1.0;
  const std::vector<dg::SeamLocation> misplaced{{&first.site, &first.docker, {}}, {&second.site, &second.docker, off}};
  CHECK_FALSE(dg::plane_between_sides(surface, misplaced, 0.25 * kEps));
}

TEST_CASE("seam plane: a patch ringed by its band has no plane between docker and rest", "[grammar][seam_plane]") {
  const dg::VoxelSurface surface = two_bars();
  // A patch of the lower bar's top face (x in [5, 6)), ringed by three voxels of band.
  auto top = [](const dg::Vec3& p) { return p.y() < 2.0 && p.z() > 1.0; };
  auto in_patch = [](const dg::Vec3& p) { return p.x() >= 5.0 && p.x() < 6.0 && p.y() > 0.4 && p.y() < 0.7; };
  auto in_ring = [](const dg::Vec3& p) { return p.x() >= 4.7 && p.x() < 6.3 && p.y() > 0.1 && p.y() < 1.0; };
  const std::vector<std::uint32_t> docker = cells_where(surface, [&](const dg::Vec3& p) { return top(p) && in_patch(p); });
  const std::vector<std::uint32_t> site =
      cells_where(surface, [&](const dg::Vec3& p) { return top(p) && in_ring(p) && !in_patch(p); });
  REQUIRE_FALSE(docker.empty());
  REQUIRE_FALSE(site.empty());
  const std::vector<dg::SeamLocation> one{{&site, &docker, {}}};
  CHECK_FALSE(dg::plane_between_sides(surface, one, 0.25 * kEps));
}
