// The uniform segment grid of guided growth against brute force, and the 2D helpers.

#include "geometry/random.h"
#include "synthesis/segment2d.h"
#include "synthesis/segment_grid.h"

#include <catch2/catch.hpp>

#include <limits>

TEST_CASE("point in polygon and self-intersection of guide polygons", "[growth]") {
  const std::vector<dg::Vec2> square{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  CHECK(dg::point_in_polygon({1, 1}, square));
  CHECK_FALSE(dg::point_in_polygon({3, 1}, square));
  CHECK_FALSE(dg::polygon_self_intersects(square));
  CHECK(dg::polygon_self_intersects({{0, 0}, {2, 2}, {2, 0}, {0, 2}}));  // bow tie
  CHECK(dg::polygon_self_intersects({{0, 0}, {2, 0}, {1, 0}, {1, 1}}));  // folds back on itself
  CHECK(dg::polygon_signed_area(square) == 4);
  CHECK(dg::turn_toward(0, {0, 1}) == Approx(90));
  CHECK(dg::turn_toward(90, {1, 0}) == Approx(-90));
}

TEST_CASE("segment grid queries agree with brute force", "[growth]") {
  dg::Random random(7);
  dg::SegmentGrid grid;
  grid.reset({0, 0}, {100, 100}, 2000, 0.5);
  std::vector<dg::GridSegment> all;
  for (int i = 0; i < 2000; ++i) {
    const dg::Vec2 a(random.uniform(-5, 105), random.uniform(-5, 105));  // some stick out of the box
    const dg::Vec2 b = a + dg::Vec2(random.uniform(-3, 3), random.uniform(-3, 3));
    all.push_back({a, b, static_cast<double>(i)});
    CHECK(grid.insert(all.back()) == static_cast<std::size_t>(i));
  }
  for (int q = 0; q < 300; ++q) {
    const dg::Vec2 p(random.uniform(-10, 110), random.uniform(-10, 110));
    const dg::Vec2 end = p + dg::Vec2(random.uniform(-40, 40), random.uniform(-40, 40));
    double best_t = std::numeric_limits<double>::infinity(), best_d = best_t;
    for (const dg::GridSegment& s : all) {
      if (const auto c = dg::cross_segments(p, end, s.a, s.b); c && c->s > 1e-9) best_t = std::min(best_t, c->s);
      best_d = std::min(best_d, dg::point_segment_distance(p, s.a, s.b));
    }
    const auto hit = grid.first_hit(p, end, 1e-9);
    if (std::isinf(best_t)) {
      CHECK_FALSE(hit);
    } else {
      REQUIRE(hit);
      CHECK(hit->t == Approx(best_t));
    }
    const auto nearest = grid.nearest(p);
    REQUIRE(nearest);
    CHECK(nearest->t == Approx(best_d));
  }
}
