// one_sided_up_axis: a scan seen from above (roof and walls, no floor) faces up along one axis
// and never down; closed meshes, facades and clouds without normals give no axis.

#include "geometry/one_sided_axis.h"

#include "geometry/model_io.h"
#include "geometry/submesh.h"
#include "geometry/surface_sampling.h"
#include "support/corpus.h"
#include "support/shapes.h"

#include <catch2/catch.hpp>

#include <optional>
#include <vector>

namespace {

// `mesh` without the triangles facing -axis (normals within 60 degrees of it).
dg::TriangleMesh without_faces_down(const dg::TriangleMesh& mesh, int axis) {
  std::vector<std::size_t> kept;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (mesh.area_vector(t).normalized()[axis] > -0.5) kept.push_back(t);
  return dg::submesh(mesh, kept);
}

dg::Model mesh_model(dg::TriangleMesh mesh) {
  dg::Model model;
  model.mesh = std::move(mesh);
  return model;
}

dg::Model cloud_model(dg::PointCloud cloud) {
  dg::Model model;
  model.cloud = std::move(cloud);
  return model;
}

}  // namespace

TEST_CASE("one_sided_up_axis: a tower without its floor, as a mesh or a scan, faces up along its height", "[geometry]") {
  // 3 x 5 wide, 8 tall along z: roof 15 of 143 units^2 (10.5 %), walls the rest.
  const dg::TriangleMesh tower = without_faces_down(dg::test::make_box(dg::Vec3(0, 0, 0), dg::Vec3(3, 5, 8)), 2);
  const std::optional<dg::AxisFacing> from_mesh = dg::one_sided_up_axis(mesh_model(tower));
  REQUIRE(from_mesh);
  CHECK(from_mesh->axis == 2);
  CHECK(from_mesh->up == Approx(15.0 / 143.0));
  CHECK(from_mesh->down == 0.0);
  CHECK(from_mesh->across == Approx(128.0 / 143.0));

  const dg::PointCloud scan = dg::sample_surface(tower, 20000, 7);
  const std::optional<dg::AxisFacing> from_scan = dg::one_sided_up_axis(cloud_model(scan));
  REQUIRE(from_scan);
  CHECK(from_scan->axis == 2);
  CHECK(from_scan->up == Approx(15.0 / 143.0).margin(0.01));

  // The same tower stood on y (its floor, facing -y, left out).
  const dg::TriangleMesh y_tower = without_faces_down(dg::test::make_box(dg::Vec3(0, 0, 0), dg::Vec3(3, 8, 5)), 1);
  const std::optional<dg::AxisFacing> y_up = dg::one_sided_up_axis(mesh_model(y_tower));
  REQUIRE(y_up);
  CHECK(y_up->axis == 1);
}

TEST_CASE("one_sided_up_axis: closed meshes, one-sided facades and clouds without normals give no axis", "[geometry]") {
  // Closed: every direction faces as much surface as its opposite.
  CHECK_FALSE(dg::one_sided_up_axis(mesh_model(dg::test::make_box(dg::Vec3(0, 0, 0), dg::Vec3(3, 5, 8)))));
  // A facade slab 10 wide, 8 tall, 0.5 deep with no back: it faces +z alone, but it is thin
  // along z and almost nothing of it faces across z.
  const dg::TriangleMesh facade = without_faces_down(dg::test::make_box(dg::Vec3(0, 0, 0), dg::Vec3(10, 8, 0.5)), 2);
  CHECK_FALSE(dg::one_sided_up_axis(mesh_model(facade)));
  // A scan without normals carries no side.
  dg::PointCloud bare = dg::sample_surface(without_faces_down(dg::test::make_box(dg::Vec3(0, 0, 0), dg::Vec3(3, 5, 8)), 2), 5000, 3);
  bare.normals.clear();
  CHECK_FALSE(dg::one_sided_up_axis(cloud_model(bare)));
}

// The CGAL building scan (100k points with normals, 55 long along y, 18 tall along z) was drawn
// y-up, standing on its end as a tower: 18 % of its points face +z (roofs), one faces -z. The
// Hochhaus Asemwald (an OBJ without floors) faces +y and never -y, its file's y-up.
TEST_CASE("corpus: the CGAL building scan is seen from above along z, the Hochhaus along y", "[geometry][corpus]") {
  const auto scan = dg::test::corpus_file_if_present("meshes/pointcloud-cgal-building/building.ply");
  const auto tower = dg::test::corpus_file_if_present("meshes/arch-fg-hochhaus-asemwald/hochhaus_asemwald.obj");
  if (!scan || !tower) return;
  const std::optional<dg::AxisFacing> building = dg::one_sided_up_axis(dg::read_model(*scan));
  REQUIRE(building);
  CHECK(building->axis == 2);
  CHECK(building->up == Approx(0.18).margin(0.01));
  CHECK(building->down < 1e-4);
  const std::optional<dg::AxisFacing> hochhaus = dg::one_sided_up_axis(dg::read_model(*tower));
  REQUIRE(hochhaus);
  CHECK(hochhaus->axis == 1);
}
