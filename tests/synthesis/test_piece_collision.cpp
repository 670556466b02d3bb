// Collision checks between placed pieces (synthesis/piece_collision.h).

#include "synthesis/piece_collision.h"

#include <catch2/catch.hpp>

namespace {

// One triangle with the given corners.
dg::TriangleMesh triangle(const dg::Vec3& a, const dg::Vec3& b, const dg::Vec3& c) {
  dg::TriangleMesh mesh;
  mesh.positions = {a, b, c};
  mesh.triangles = {{0, 1, 2}};
  return mesh;
}

// A flat triangle in the plane z = 0 around (x, 0), and one standing through it.
dg::TriangleMesh flat(double x) { return triangle({x - 1, -1, 0}, {x + 1, -1, 0}, {x, 1, 0}); }
dg::TriangleMesh standing(double x) { return triangle({x - 0.5, 0, -1}, {x + 0.5, 0, -1}, {x, 0, 1}); }

}  // namespace

TEST_CASE("add_unless_collides adds only a piece that crosses no placed piece", "[synthesis][collision]") {
  const dg::SeamContact nowhere = [](const dg::Vec3&) { return false; };
  dg::PieceCollisions collisions(1e-6);
  collisions.add(flat(0));
  CHECK(collisions.collides(standing(0), nowhere));
  CHECK_FALSE(collisions.add_unless_collides(standing(0), nowhere));
  CHECK(collisions.pieces() == 1);
  CHECK(collisions.add_unless_collides(flat(10), nowhere));  // far away
  CHECK(collisions.pieces() == 2);
  // The structure built for the check of the piece added last serves later checks against it.
  CHECK_FALSE(collisions.add_unless_collides(standing(10), nowhere));
  CHECK_FALSE(collisions.collides(standing(20), nowhere));
  // Crossings the caller accepts as contact at a seam are no collision.
  const dg::SeamContact everywhere = [](const dg::Vec3&) { return true; };
  CHECK(collisions.add_unless_collides(standing(0), everywhere));
  CHECK(collisions.pieces() == 3);
}
