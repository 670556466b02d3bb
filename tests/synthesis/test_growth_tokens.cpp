// Token reservation of guided growth (Beneš et al. 2011 §3.3.2 and §5.2): a link query that
// selects a link reserves a token for its branch, other branches no longer see that link, the
// token is used when the branch crosses and freed when the branch is erased.

#include "grammar/lsystem_text.h"
#include "synthesis/growth.h"

#include <catch2/catch.hpp>

#include <algorithm>

namespace {

std::vector<dg::Vec2> box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

std::size_t count_id(const std::vector<dg::GridSegment>& segments, double id) {
  return static_cast<std::size_t>(
      std::count_if(segments.begin(), segments.end(), [id](const dg::GridSegment& s) { return s.id == id; }));
}

// §5.2's feedback: a tip circles inside a 10 x 10 guide (6 degrees per step of 0.3) and looks
// for the closest link with ?DL; closer than 2.5 it sends a lateral branch toward it, whose
// first segment has id 100 + link and whose later segments 200 + link (?XS). Links on the
// right, top and left edges lead to three small guides.
dg::GrowthScene spiral_scene(int tokens) {
  const char* spiral =
      "axiom: ?seed\n"
      "?seed(x, y, h) -> T(0)\n"
      "T(n) : n < 58 -> +(6) ?X(0.3) ?DL(0.3) T(n + 1)\n"
      "?X(found, id, delta) : found -> cut\n"
      "?X(found, id, delta) : !found -> F(delta)\n"
      "?DL(found, d, b, id, delta) : found == 3 && d < 2.5 -> [+(b) ?XS(delta, 100 + id) ?DLI(id, delta)]\n"
      "?DL(found, d, b, id, delta) : found != 3 || d >= 2.5 -> ε\n"
      "?XS(found, id, delta, tag) : found == 3 -> F(delta) cut\n"
      "?XS(found, id, delta, tag) : found == 1 || found == 2 -> cut\n"
      "?XS(found, id, delta, tag) : found == 0 -> F(delta)\n"
      "?DLI(found, d, b, id, link, delta) : found -> +(b * 0.5) ?XS(delta, 200 + link) ?DLI(link, delta)\n"
      "?DLI(found, d, b, id, link, delta) : !found -> ε\n";
  dg::GrowthScene scene;
  scene.lsystems.push_back({"spiral", dg::parse_lsystem_text(spiral, "spiral.ls")});
  scene.lsystems.push_back({"lateral", dg::parse_lsystem_text("axiom: ?seed\n?seed(x, y, h, tag) -> F(1)\n", "lateral.ls")});
  scene.guides.push_back({"main", box(0, 0, 10, 10), 0, {{{5, 2}, 0, {}}}});
  scene.guides.push_back({"east", box(10, 0, 14, 10), 1, {}});
  scene.guides.push_back({"north", box(0, 10, 10, 14), 1, {}});
  scene.guides.push_back({"west", box(-4, 0, 0, 10), 1, {}});
  scene.links.push_back({0, 1, 1, 3, tokens, 0});  // right edge -> east's left edge
  scene.links.push_back({0, 2, 2, 0, tokens, 0});  // top edge -> north's bottom edge
  scene.links.push_back({0, 3, 3, 1, tokens, 0});  // left edge -> west's right edge
  return scene;
}

std::vector<dg::Vec2> unit_box() { return box(0, 0, 10, 10); }

}  // namespace

TEST_CASE("a spiral sends exactly one lateral branch toward each link (§5.2 feedback)", "[growth]") {
  const dg::GrowthResult result = dg::grow(spiral_scene(1));
  const std::vector<dg::GridSegment>& main = result.guides[0].segments;
  for (std::size_t link = 0; link < 3; ++link) {
    INFO("link " << link);
    CHECK(count_id(main, 100.0 + static_cast<double>(link)) == 1);  // one branch started toward it
    CHECK(count_id(main, 200.0 + static_cast<double>(link)) >= 5);   // and grew to the edge
    CHECK(result.tokens[link].used == 1);
    CHECK(result.tokens[link].reserved == 0);
    const dg::GuideGrowth& target = result.guides[link + 1];
    REQUIRE(target.received.size() == 1);
    CHECK(target.received[0].values == std::vector<double>{200.0 + static_cast<double>(link)});  // ?XS's tag travels
    CHECK(target.segments.size() == 1);
  }
  // Links without tokens only steer: nothing reserves them, so the tip sends a branch at
  // every step it is near one (the behaviour the reservation prevents).
  const dg::GrowthResult steering = dg::grow(spiral_scene(0));
  for (std::size_t link = 0; link < 3; ++link) {
    INFO("link " << link);
    CHECK(count_id(steering.guides[0].segments, 100.0 + static_cast<double>(link)) >= 3);
    CHECK(steering.guides[link + 1].received.empty());
  }
}

TEST_CASE("a reserved token is hidden from other branches and freed when its branch is erased", "[growth]") {
  // Seed 0 (lifetime 3) reserves the only token with ?DL, walks 3 steps toward the link and
  // is erased; seed 1 sees no link while the token is reserved (it draws a short marker each
  // step it waits), then reserves it, walks up and crosses.
  const char* rules =
      "axiom: ?seed(100)\n"
      "?seed(x, y, h, life) -> ?DL(1, life)\n"
      "?DL(found, d, b, id, delta, life) : found && life > 0 -> ?X(delta) ?DL(delta, life - 1)\n"
      "?DL(found, d, b, id, delta, life) : !found && life > 0 -> [+(90) F(0.1)] ?DL(delta, life - 1)\n"
      "?DL(found, d, b, id, delta, life) : life <= 0 -> ε\n"
      "?X(found, id, delta) : found -> F(delta) cut\n"
      "?X(found, id, delta) : !found -> F(delta)\n";
  dg::GrowthScene scene;
  scene.lsystems.push_back({"seeker", dg::parse_lsystem_text(rules, "seeker.ls")});
  scene.guides.push_back({"A", unit_box(), 0, {{{3, 1}, 90, {3}}, {{6, 1}, 90, {100}}}});
  scene.guides.push_back({"B", box(0, 10, 10, 20), std::nullopt, {}});
  scene.links.push_back({0, 2, 1, 0, 1, 0});
  const dg::GrowthResult result = dg::grow(scene);
  const std::vector<dg::GridSegment>& segments = result.guides[0].segments;
  CHECK(count_id(segments, 0) == 3);  // seed 0: y from 1 to 4
  std::size_t markers = 0, walked = 0;
  for (const dg::GridSegment& s : segments)
    if (s.id == 1) ++((s.b - s.a).norm() < 0.5 ? markers : walked);
  CHECK(markers == 4);  // steps 1-4: the token is reserved by seed 0 until its branch is erased in step 4
  CHECK(walked == 9);   // y from 1 to 10, the last segment crossing the link's edge
  CHECK(result.tokens[0].used == 1);
  CHECK(result.tokens[0].free == 0);
  REQUIRE(result.guides[1].received.size() == 1);
  CHECK(result.guides[1].received[0].t == Approx(0.4));  // seed 1's crossing at x = 6
}
