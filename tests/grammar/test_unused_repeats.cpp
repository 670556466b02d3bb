// Repeats a model shows that its grids do not use (what the analyze report lists as not built).

#include "grammar/unused_repeats.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using dg::Vec3;

namespace {

dg::SymmetryFamily translation(const Vec3& t, std::size_t repeats) {
  dg::SymmetryFamily family;
  family.kind = "translation";
  family.generator.translation = t;
  family.count = repeats;
  return family;
}

dg::SymmetryFamily rotation(double degrees, int order, std::size_t repeats) {
  dg::SymmetryFamily family;
  family.kind = "rotation";
  family.generator.rotation = Eigen::AngleAxisd(degrees * std::numbers::pi / 180.0, Vec3::UnitZ()).toRotationMatrix();
  family.order = order;
  family.count = repeats;
  return family;
}

dg::GridRule grid_along(const std::vector<Vec3>& translations) {
  dg::GridRule grid;
  for (const Vec3& t : translations) {
    dg::GridDirection d;
    d.translation = t;
    d.direction = t.normalized();
    d.pitch = t.norm();
    grid.directions.push_back(d);
  }
  return grid;
}

}  // namespace

TEST_CASE("unused repeats: translations outside every grid's span, rotations short of a full turn", "[grammar][grid]") {
  dg::SymmetryResult symmetries;
  symmetries.families = {
      translation(Vec3(2, 0, 0), 5),     // 0: a grid direction
      translation(Vec3(4, 0, 0), 2),     // 1: twice it
      translation(Vec3(2, 3, 0), 2),     // 2: a diagonal step of the 2-grid below
      translation(Vec3(0, 0, 1.5), 3),   // 3: across the grids
      translation(Vec3(0, 0, 7), 1),     // 4: no repeat
      rotation(30.0, 12, 11),            // 5: a full turn of 12 teeth
      rotation(18.0, 20, 4),             // 6: five columns on a quarter circle
      rotation(25.0, 0, 3),              // 7: an angle that divides no full turn
      rotation(180.0, 2, 1),             // 8: a half turn, no repeat
  };
  SECTION("a 2-grid along x and y") {
    const dg::UnusedRepeats unused = dg::unused_repeats(symmetries, {grid_along({Vec3(2, 0, 0), Vec3(0, 3, 0)})}, 2);
    CHECK(unused.translations == std::vector<std::size_t>{3});
    CHECK(unused.partial_turns == std::vector<std::size_t>{6, 7});
  }
  SECTION("a 1-grid along x: the diagonal step is unused too") {
    const dg::UnusedRepeats unused = dg::unused_repeats(symmetries, {grid_along({Vec3(2, 0, 0)})}, 2);
    CHECK(unused.translations == std::vector<std::size_t>{2, 3});
  }
  SECTION("no grid; three repeats required") {
    const dg::UnusedRepeats unused = dg::unused_repeats(symmetries, {}, 3);
    CHECK(unused.translations == std::vector<std::size_t>{0, 3});
    CHECK(unused.partial_turns == std::vector<std::size_t>{6, 7});
  }
}

TEST_CASE("unused repeats: a translation whose grids span less than half of its repeats", "[grammar][grid]") {
  // 27 repeats of a fin's pitch (2 along x); wall brackets across the fins leave a grid only
  // where there are none.
  dg::SymmetryResult symmetries;
  symmetries.families = {translation(Vec3(2, 0, 0), 27), translation(Vec3(0, 3, 0), 4)};
  auto counted = [](dg::GridRule grid, std::vector<int> counts) {
    for (std::size_t i = 0; i < counts.size(); ++i) grid.directions[i].count = counts[i];
    return grid;
  };
  SECTION("two units of twice the pitch: 4 of 27 repeats") {
    const dg::UnusedRepeats unused = dg::unused_repeats(symmetries, {counted(grid_along({Vec3(4, 0, 0), Vec3(0, 3, 0)}), {2, 4})}, 2);
    REQUIRE(unused.short_runs.size() == 1);
    CHECK(unused.short_runs[0].family == 0);
    CHECK(unused.short_runs[0].spanned == Approx(4.0));
    CHECK(unused.translations.empty());
  }
  SECTION("two stretches, one either way along the fins: 6 + 8 of 27 repeats") {
    const dg::UnusedRepeats unused =
        dg::unused_repeats(symmetries, {counted(grid_along({Vec3(2, 0, 0)}), {6}), counted(grid_along({Vec3(-4, 0, 0)}), {4})}, 2);
    CHECK(unused.short_runs.empty());
    CHECK(unused.translations == std::vector<std::size_t>{1});
  }
  SECTION("a screw whose slide runs along the fins spans none of them") {
    dg::GridRule screw = counted(grid_along({Vec3(2, 0, 0)}), {20});
    screw.directions[0].motion.rotation = Eigen::AngleAxisd(0.5, Vec3::UnitX()).toRotationMatrix();
    const dg::UnusedRepeats unused = dg::unused_repeats(symmetries, {counted(grid_along({Vec3(4, 0, 0)}), {2}), screw}, 2);
    REQUIRE(unused.short_runs.size() == 1);
    CHECK(unused.short_runs[0].spanned == Approx(4.0));
  }
}
