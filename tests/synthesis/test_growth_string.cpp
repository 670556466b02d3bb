// Guided growth strings: stretches that no step changes are redrawn when the turtle reaches
// them at another pose and vanish when a cut erases them; Table 2's idin (?XS); motif copies
// block ?X like segments.

#include "grammar/lsystem_text.h"
#include "synthesis/growth.h"

#include <catch2/catch.hpp>

#include <algorithm>

namespace {

std::vector<dg::Vec2> box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

// One 10 x 10 guide running `rules` from the given seeds.
dg::GrowthScene one_guide(const std::string& rules, const std::vector<dg::GuideSeed>& seeds) {
  dg::GrowthScene scene;
  scene.lsystems.push_back({"rules", dg::parse_lsystem_text(rules, "rules.ls")});
  scene.guides.push_back({"A", box(0, 0, 10, 10), 0, seeds});
  return scene;
}

bool near(const dg::Vec2& a, const dg::Vec2& b) { return (a - b).norm() < 1e-9; }

std::size_t count_id(const std::vector<dg::GridSegment>& segments, double id) {
  return static_cast<std::size_t>(
      std::count_if(segments.begin(), segments.end(), [id](const dg::GridSegment& s) { return s.id == id; }));
}

}  // namespace

TEST_CASE("finished modules are redrawn where the turtle reaches them after earlier modules grow", "[growth]") {
  // F and its branch never change after step 1, but A pushes them up by 1 in each of 5 steps.
  const char* rules =
      "axiom: ?seed\n"
      "?seed(x, y, h) -> A(5) F(1) [+(90) F(1)]\n"
      "A(n) : n > 0 -> f(1) A(n - 1)\n";
  const dg::GrowthResult result = dg::grow(one_guide(rules, {{{5, 0}, 90, {}}}));
  const std::vector<dg::GridSegment>& segments = result.guides[0].segments;
  REQUIRE(segments.size() == 2);
  CHECK(near(segments[0].a, {5, 5}));
  CHECK(near(segments[0].b, {5, 6}));
  CHECK(near(segments[1].a, {5, 6}));
  CHECK(near(segments[1].b, {4, 6}));
}

TEST_CASE("a cut erases finished modules after it together with their elements", "[growth]") {
  // The two F(1) of the branch are finished after step 1; D's cut erases them in step 3.
  const char* rules =
      "axiom: ?seed\n"
      "?seed(x, y, h) -> [C F(1) F(1)] F(2)\n"
      "C -> D\n"
      "D -> cut\n";
  const dg::GrowthResult result = dg::grow(one_guide(rules, {{{5, 1}, 90, {}}}));
  REQUIRE(result.guides[0].segments.size() == 1);
  CHECK(near(result.guides[0].segments[0].a, {5, 1}));
  CHECK(near(result.guides[0].segments[0].b, {5, 3}));
}

TEST_CASE("?XS gives the tested segment its idin, and queries report it", "[growth]") {
  // Seed 0 walks up x = 3 and tags its k-th segment (y from k+1 to k+2) with 100 + k. Seed 1
  // walks right along y = 2.5, hits that column and draws a marker F(id / 100) upwards.
  const char* rules =
      "axiom: ?seed(0)\n"
      "?seed(x, y, h, kind) : kind == 0 -> ?XS(1, 100)\n"
      "?seed(x, y, h, kind) : kind == 1 -> ?X(1)\n"
      "?XS(found, id, delta, tag) : found -> F(delta) cut\n"
      "?XS(found, id, delta, tag) : !found -> F(delta) ?XS(delta, tag + 1)\n"
      "?X(found, id, delta) : found == 1 -> +(90) F(id / 100)\n"
      "?X(found, id, delta) : found != 1 && found -> cut\n"
      "?X(found, id, delta) : !found -> F(delta) ?X(delta)\n";
  const dg::GrowthResult result = dg::grow(one_guide(rules, {{{3, 1}, 90, {0}}, {{0.5, 2.5}, 0, {1}}}));
  const std::vector<dg::GridSegment>& segments = result.guides[0].segments;
  for (int k = 0; k < 9; ++k) {
    INFO("segment " << k);
    CHECK(count_id(segments, 100 + k) == 1);
  }
  CHECK(count_id(segments, 0) == 0);  // every segment of seed 0 carries its idin
  // Seed 1 (elements with id 1) met segment 101 (y from 2 to 3): its marker is 1.01 long.
  const auto marker = std::find_if(segments.begin(), segments.end(), [](const dg::GridSegment& s) {
    return s.id == 1 && std::abs(s.a.x() - s.b.x()) < 1e-12;
  });
  REQUIRE(marker != segments.end());
  CHECK((marker->b - marker->a).norm() == Approx(1.01));
  CHECK(marker->a.x() == Approx(2.5));
}

TEST_CASE("motif copies block ?X like drawn segments", "[growth]") {
  // Seed 0 places a 2 x 2 square motif around (5, 2); seed 1 walks right along y = 2 from
  // x = 0.5 and stops at the square's left side (x = 4) instead of crossing it to the guide's edge.
  const char* rules =
      "axiom: ?seed(0)\n"
      "motif B: M -1 -1 L 1 -1 L 1 1 L -1 1 Z\n"
      "?seed(x, y, h, kind) : kind == 0 -> B\n"
      "?seed(x, y, h, kind) : kind == 1 -> ?X(1)\n"
      "?X(found, id, delta) : found -> cut\n"
      "?X(found, id, delta) : !found -> F(delta) ?X(delta)\n";
  const dg::GrowthResult result = dg::grow(one_guide(rules, {{{5, 2}, 90, {0}}, {{0.5, 2}, 0, {1}}}));
  CHECK(result.guides[0].motifs.size() == 1);
  const std::vector<dg::GridSegment>& segments = result.guides[0].segments;
  CHECK(segments.size() == 3);
  for (const dg::GridSegment& s : segments) CHECK(std::max(s.a.x(), s.b.x()) <= 4 + 1e-9);
}
