#include "geometry/box_overlap.h"

#include <catch2/catch.hpp>

using dg::Vec3;

TEST_CASE("triangle-box overlap: inside, outside, touching", "[geometry]") {
  const Vec3 lo(0, 0, 0), hi(1, 1, 1);
  CHECK(dg::triangle_box_overlap({0.2, 0.2, 0.5}, {0.8, 0.2, 0.5}, {0.5, 0.8, 0.5}, lo, hi));
  CHECK_FALSE(dg::triangle_box_overlap({2, 0, 0}, {3, 0, 0}, {2, 1, 0}, lo, hi));
  // Large triangle cutting through the box with all corners outside.
  CHECK(dg::triangle_box_overlap({-5, -5, 0.5}, {5, -5, 0.5}, {0, 10, 0.5}, lo, hi));
  // Plane passes near the box corner but misses it (only the normal axis separates).
  CHECK_FALSE(dg::triangle_box_overlap({3.1, 0, 0}, {0, 3.1, 0}, {0, 0, 3.1}, lo, hi));
  CHECK(dg::triangle_box_overlap({3, 0, 0}, {0, 3, 0}, {0, 0, 3}, lo, hi));  // touches corner (1,1,1)
  // Only a corner of the triangle touches the box corner.
  CHECK(dg::triangle_box_overlap({1, 1, 1}, {2, 1, 1.5}, {1.5, 2, 1}, lo, hi));
  // An edge of the triangle lies on a box edge.
  CHECK(dg::triangle_box_overlap({0, 1, 1}, {1, 1, 1}, {0.5, 2, 2}, lo, hi));
  // Just beyond the face.
  CHECK_FALSE(dg::triangle_box_overlap({1.0000001, 0, 0}, {1.5, 0, 1}, {1.5, 1, 0}, lo, hi));
}

TEST_CASE("segment-box overlap through degenerate triangles", "[geometry]") {
  const Vec3 lo(0, 0, 0), hi(1, 1, 1);
  const Vec3 a(-1, 0.5, 0.5), b(2, 0.5, 0.5);
  CHECK(dg::triangle_box_overlap(a, b, b, lo, hi));
  // Diagonal segment that passes the box's corner region without touching it.
  const Vec3 c(1.2, -0.5, 0.5), d(2.5, 0.8, 0.5);
  CHECK_FALSE(dg::triangle_box_overlap(c, d, d, lo, hi));
  // Segment ending exactly on a face.
  CHECK(dg::triangle_box_overlap({2, 0.5, 0.5}, {1, 0.5, 0.5}, {1, 0.5, 0.5}, lo, hi));
}

TEST_CASE("a face on a voxel plane at a rounded coordinate touches both voxels", "[geometry]") {
  // x = 3.1 with eps = 0.1: 31 * 0.1 is not exactly 3.1 in binary; the face must still touch.
  const double eps = 0.1;
  const dg::Vec3 a(3.1, 0.31, 0.52), b(3.1, 0.77, 0.52), c(3.1, 0.31, 0.93);
  for (int i : {30, 31})
    CHECK(dg::triangle_box_overlap(a, b, c, dg::Vec3(i * eps, 3 * eps, 5 * eps), dg::Vec3((i + 1) * eps, 4 * eps, 6 * eps)));
}
