// When two context-free productions count as one: the same shape, however it is triangulated.

#include "grammar/same_production.h"

#include "support/shapes.h"

#include <catch2/catch.hpp>

using dg::Vec3;

namespace {

// The unit square [x, x + 1] x [y, y + 1] in the plane z = 0, as two triangles.
dg::TriangleMesh square(double x, double y) {
  dg::TriangleMesh mesh;
  mesh.positions = {Vec3(x, y, 0), Vec3(x + 1, y, 0), Vec3(x + 1, y + 1, 0), Vec3(x, y + 1, 0)};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

dg::ShapeProduction leaf(std::size_t lhs, dg::TriangleMesh terminal) {
  dg::ShapeProduction p;
  p.lhs = lhs;
  p.terminal = std::move(terminal);
  return p;
}

}  // namespace

TEST_CASE("same production: a terminal triangulated differently is the same, another shape is not", "[grammar][context_free]") {
  const double tolerance = 0.05;
  const dg::TriangleMesh box = dg::test::make_box(Vec3(0, 0, 0), Vec3(1, 2, 3));
  const dg::ShapeProduction p = leaf(0, box);
  CHECK(dg::same_production(p, p, tolerance));
  // Three times the triangles, the same surface.
  const dg::ShapeProduction retriangulated = leaf(0, dg::test::split_at_centroids(box));
  REQUIRE(retriangulated.terminal.triangles.size() == 3 * box.triangles.size());
  CHECK(dg::same_production(p, retriangulated, tolerance));
  CHECK(dg::same_production(retriangulated, p, tolerance));
  // Another left side, a corner moved by 4 tolerances, the box moved by 2 tolerances.
  CHECK_FALSE(dg::same_production(p, leaf(1, box), tolerance));
  dg::TriangleMesh dented = box;
  dented.positions[0] += Vec3(0.2, 0.2, 0.2);
  CHECK_FALSE(dg::same_production(p, leaf(0, dented), tolerance));
  dg::TriangleMesh moved = box;
  for (Vec3& q : moved.positions) q.x() += 0.1;
  CHECK_FALSE(dg::same_production(p, leaf(0, moved), tolerance));
  // Two squares in opposite corners of the same box, against the other two corners: the same
  // area and bounding box, other surfaces.
  dg::TriangleMesh diagonal = square(0, 0), other_diagonal = square(0, 1);
  dg::test::append(diagonal, square(2, 1));
  dg::test::append(other_diagonal, square(2, 0));
  CHECK_FALSE(dg::same_production(leaf(0, diagonal), leaf(0, other_diagonal), tolerance));
  CHECK(dg::same_production(leaf(0, diagonal), leaf(0, dg::test::split_at_centroids(diagonal)), tolerance));
  // Materials: the same surface with another material on one triangle is another production.
  dg::TriangleMesh painted = box, repainted = box;
  painted.materials.assign(box.triangles.size(), 0);
  repainted.materials = painted.materials;
  repainted.materials[0] = 1;
  CHECK_FALSE(dg::same_production(leaf(0, painted), leaf(0, repainted), tolerance));
}

TEST_CASE("same production: a hidden second layer of the same faces is the same shape", "[grammar][context_free]") {
  // The Scopia chandelier's copies of one part differ so: one holds its 810 duplicated triangles
  // (half of them cut otherwise), the other not, and areas of 264 against 153 units^2 kept them
  // apart; every variant that swapped them was the exemplar to within 0.01 eps.
  const double tolerance = 0.05;
  const dg::TriangleMesh box = dg::test::make_box(Vec3(0, 0, 0), Vec3(1, 2, 3));
  dg::TriangleMesh doubled = box;
  dg::test::append(doubled, dg::test::split_at_centroids(box));
  CHECK(dg::same_production(leaf(0, box), leaf(0, doubled), tolerance));
  CHECK(dg::same_production(leaf(0, doubled), leaf(0, box), tolerance));
  // A second layer a little outside is another shape.
  dg::TriangleMesh shell = box;
  dg::test::append(shell, dg::test::make_box(Vec3(-0.2, -0.2, -0.2), Vec3(1.2, 2.2, 3.2)));
  CHECK_FALSE(dg::same_production(leaf(0, box), leaf(0, shell), tolerance));
}
