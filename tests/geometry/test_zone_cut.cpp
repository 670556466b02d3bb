// Cutting a mesh along planes (zone cut): touching parts cut along the same lines stay apart.

#include "geometry/zone_cut.h"

#include "geometry/topology.h"
#include "support/shapes.h"

#include <catch2/catch.hpp>

using dg::Vec3;

TEST_CASE("zone cut: a leg's top and the seat's underside on it, cut along crossing planes, stay two parts", "[geometry]") {
  // The leg [0.4, 0.6]^2 x [0, 1] touches the seat [0, 1]^2 x [1, 1.1] face to face. The planes
  // x = 0.5 and y = 0.5 cross both the leg's top and the seat's underside, where each cut makes a
  // vertex at (0.5, 0.5, 1) and chords along the same lines.
  dg::TriangleMesh chair = dg::test::make_box(Vec3(0.4, 0.4, 0), Vec3(0.6, 0.6, 1));
  dg::test::append(chair, dg::test::make_box(Vec3(0, 0, 1), Vec3(1, 1, 1.1)));
  const std::vector<dg::PlaneFamily> planes{{Vec3::UnitX(), {0.5}}, {Vec3::UnitY(), {0.5}}};
  const dg::ZoneCut cut = dg::cut_zone(chair, std::vector<char>(chair.triangles.size(), 1), planes, 1e-9);
  REQUIRE(cut.mesh.triangles.size() > chair.triangles.size());
  std::size_t parts = 0;
  dg::triangle_components(cut.mesh, &parts);
  CHECK(parts == 2);
  CHECK(dg::is_closed_and_oriented(cut.mesh));
  CHECK(cut.mesh.area() == Approx(chair.area()));
}
