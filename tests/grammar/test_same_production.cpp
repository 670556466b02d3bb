// When two context-free productions count as one: the same shape, however it is triangulated.

#include "grammar/same_production.h"

#include "support/shapes.h"

#include <catch2/catch.hpp>

using dg::Vec3;

namespace {

// `mesh` with every triangle split at its centroid into three: the same surface.
dg::TriangleMesh split_at_centroids(const dg::TriangleMesh& mesh) {
  dg::TriangleMesh split = mesh;
  split.triangles.clear();
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    const auto m = static_cast<std::uint32_t>(split.positions.size());
    split.positions.push_back((a + b + c) / 3.0);
    const dg::Triangle& tri = mesh.triangles[t];
    split.triangles.insert(split.triangles.end(), {{tri[0], tri[1], m}, {tri[1], tri[2], m}, {tri[2], tri[0], m}});
  }
  return split;
}

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
  const dg::ShapeProduction retriangulated = leaf(0, split_at_centroids(box));
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
  CHECK(dg::same_production(leaf(0, diagonal), leaf(0, split_at_centroids(diagonal)), tolerance));
  // Materials: the same surface with another material on one triangle is another production.
  dg::TriangleMesh painted = box, repainted = box;
  painted.materials.assign(box.triangles.size(), 0);
  repainted.materials = painted.materials;
  repainted.materials[0] = 1;
  CHECK_FALSE(dg::same_production(leaf(0, painted), leaf(0, repainted), tolerance));
}
