// Guided growth (Beneš et al. 2011): queries, tokens and links, limits, the palm tree of §5.1,
// incremental regrowth after mass-spring edits, and scene-file errors.

#include "grammar/lsystem_text.h"
#include "synthesis/growth.h"
#include "synthesis/growth_queries.h"
#include "synthesis/guide_edit.h"
#include "synthesis/scene_file.h"
#include "synthesis/segment2d.h"

#include <catch2/catch.hpp>

#include <algorithm>

namespace {

// A trunk-like L-system: walks ahead in steps of 1 until ?X meets an edge, then draws the last
// segment and stops (the paper's trunk rules without steering).
const char* walker =
    "axiom: ?seed\n"
    "?seed(x, y, h) -> ?X(1)\n"
    "?X(found, id, delta) : found -> F(delta) cut\n"
    "?X(found, id, delta) : !found -> F(delta) ?X(delta)\n";

std::vector<dg::Vec2> box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

// Guide A (0..10 x 0..10) with seeds at the bottom heading up, guide B above it (10..20);
// the link goes from A's top edge (edge 2) to B's bottom edge (edge 0).
dg::GrowthScene two_guides(int tokens, const std::vector<double>& seed_xs, const std::string& rules = walker) {
  dg::GrowthScene scene;
  scene.lsystems.push_back({"walker", dg::parse_lsystem_text(rules, "walker.ls")});
  dg::Guide a{"A", box(0, 0, 10, 10), 0, {}};
  for (double x : seed_xs) a.seeds.push_back({{x, 0}, 90, {}});
  scene.guides.push_back(a);
  scene.guides.push_back({"B", box(0, 10, 10, 20), 0, {}});
  scene.links.push_back({0, 2, 1, 0, tokens, 0});
  return scene;
}

bool same_segments(const std::vector<dg::GridSegment>& a, const std::vector<dg::GridSegment>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const dg::GridSegment& p, const dg::GridSegment& q) {
    return p.a == q.a && p.b == q.b && p.id == q.id;
  });
}

dg::GrowthScene palm() { return dg::read_growth_scene(std::string(DOCKGRAMMAR_SOURCE_DIR) + "/assets/scenes/palm.json"); }

std::string error_of(const std::string& json) {
  try {
    dg::parse_growth_scene(json, "bad.json", ".");
  } catch (const dg::InputError& error) {
    return error.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("queries measure links, guide edges and elements as Table 2 says", "[growth]") {
  const std::vector<dg::Vec2> square = box(0, 0, 10, 10);
  dg::SegmentGrid elements;
  elements.reset({-1, -1}, {11, 11}, 4, 0);
  elements.insert({{7, 1}, {7, 3}, 5});
  dg::GuideEnvironment environment{&square, {{square[2], square[3], 4, 2}}, &elements, {}};
  dg::TurtlePose pose{{5, 2}, 0, 1};
  const dg::SeedStart seed;

  dg::Module distance{"?DL", {0.5}};
  CHECK(dg::answer_query(distance, pose, environment, seed).selected_link == std::optional<std::size_t>(4));
  REQUIRE(distance.parameters.size() == 5);
  CHECK(distance.parameters[0] == 3);           // found: a link
  CHECK(distance.parameters[1] == Approx(8));   // d: up to y = 10
  CHECK(distance.parameters[2] == Approx(90));  // beta: turn left to face it
  CHECK(distance.parameters[3] == 4);           // id: the link index
  CHECK(distance.parameters[4] == 0.5);         // passed through

  dg::Module any{"?DA", {}};
  dg::answer_query(any, {{5, 3}, 0, 1}, environment, seed);
  CHECK(any.parameters[0] == 1);  // the element at x = 7 is closest (2 units; the bottom edge 3)
  CHECK(any.parameters[1] == Approx(2));
  CHECK(any.parameters[3] == 5);

  dg::Module ahead{"?NG", {}};
  dg::answer_query(ahead, pose, environment, seed);
  REQUIRE(ahead.parameters.size() == 3);  // the right edge (index 1), 5 ahead
  CHECK(ahead.parameters[0] == 2);
  CHECK(ahead.parameters[1] == Approx(5));
  CHECK(ahead.parameters[2] == 1);

  dg::Module blocked{"?X", {3, 9}};
  CHECK_FALSE(dg::answer_query(blocked, pose, environment, seed).crossing);
  CHECK(blocked.parameters == std::vector<double>{1, 5, 3, 9});  // hits the element first

  dg::Module free_path{"?X", {1}};
  dg::answer_query(free_path, {{5, 5}, 90, 2}, environment, seed);
  CHECK(free_path.parameters[0] == 0);
  CHECK(elements.size() == 2);  // the tested segment is now an element for later queries

  dg::Module crossing{"?X", {4, 7}};
  const auto crossed = dg::answer_query(crossing, {{2, 8}, 90, 1}, environment, seed).crossing;
  CHECK(crossing.parameters[0] == 3);
  REQUIRE(crossed);
  CHECK(crossed->links == std::vector<std::size_t>{4});
  CHECK(crossed->t == Approx(0.8));  // edge 2 runs from (10, 10) to (0, 10)
  CHECK(crossed->carried == std::vector<double>{7});

  // Id filters: ?DLI looks for link 9 only (on the left edge, farther away than link 4).
  environment.links.push_back({square[3], square[0], 9, 3});
  dg::Module only_nine{"?DLI", {9, 0.5}};
  dg::answer_query(only_nine, pose, environment, seed);
  CHECK(only_nine.parameters == std::vector<double>{3, 5, 180, 9, 9, 0.5});
  dg::Module any_link{"?DL", {}};
  dg::answer_query(any_link, pose, environment, seed);
  CHECK(any_link.parameters[3] == 9);  // unfiltered: link 9 at distance 5 beats link 4 at 8
  environment.available = [](std::size_t link) { return link != 9; };  // link 9's tokens are taken
  dg::Module hidden{"?DL", {}};
  CHECK(dg::answer_query(hidden, pose, environment, seed).selected_link == std::optional<std::size_t>(4));
  CHECK(hidden.parameters[3] == 4);
  environment.available = nullptr;
  dg::Module only_four{"?NLI", {4}};
  dg::answer_query(only_four, {{5, 2}, 90, 1}, environment, seed);
  CHECK(only_four.parameters == std::vector<double>{3, 8, 4, 4});
  dg::Module missing{"?DAI", {42}};
  dg::answer_query(missing, pose, environment, seed);
  CHECK(missing.parameters == std::vector<double>{0, 0, 0, -1, 42});
  dg::Module only_element{"?XI", {4, 5}};  // the element with id 5 is 2 ahead; edges have other numbers
  dg::answer_query(only_element, pose, environment, seed);
  CHECK(only_element.parameters[0] == 1);
  CHECK(only_element.parameters[1] == 5);

  dg::Module unknown{"?Q", {}};
  CHECK_THROWS_WITH(dg::answer_query(unknown, pose, environment, seed), Catch::Contains("unknown query module ?Q"));
}

TEST_CASE("a crossing spends a token and seeds the target edge at the matching point", "[growth]") {
  const dg::GrowthResult result = dg::grow(two_guides(1, {3}));
  REQUIRE(result.guides[1].seeds == 1);
  CHECK(result.tokens[0].used == 1);
  CHECK(result.tokens[0].free == 0);
  CHECK(result.tokens[0].reserved == 0);
  // A walks 10 unit steps up x = 3 (the last crosses y = 10, centre outside: dropped);
  // B's seed starts at (3, 10), the point under the crossing, heading up.
  CHECK(result.guides[0].segments.size() == 10);
  REQUIRE(result.guides[1].received.size() == 1);
  CHECK(result.guides[1].received[0].t == Approx(0.7));
  REQUIRE(!result.guides[1].segments.empty());
  CHECK((result.guides[1].segments.front().a - dg::Vec2(3, 10)).norm() < 1e-9);
  CHECK((result.guides[1].segments.front().b - dg::Vec2(3, 11)).norm() < 1e-9);
}

TEST_CASE("a link with zero tokens seeds nothing", "[growth]") {
  const dg::GrowthResult result = dg::grow(two_guides(0, {3}));
  CHECK(result.guides[0].segments.size() == 10);  // A still grows up to the edge
  CHECK(result.guides[1].seeds == 0);
  CHECK(result.guides[1].segments.empty());
  CHECK(result.tokens[0].used == 0);
}

TEST_CASE("two turtles competing for one token give exactly one seed", "[growth]") {
  // Both seeds reach A's top edge in the same step; the first in order reserves the only token.
  const dg::GrowthResult one = dg::grow(two_guides(1, {3, 6}));
  CHECK(one.guides[1].seeds == 1);
  CHECK(one.tokens[0].used == 1);
  CHECK(one.tokens[0].free == 0);
  REQUIRE(one.guides[1].received.size() == 1);
  CHECK(one.guides[1].received[0].t == Approx(0.7));  // the first seed's crossing at x = 3
  const dg::GrowthResult two = dg::grow(two_guides(2, {3, 6}));
  CHECK(two.guides[1].seeds == 2);
  CHECK(two.tokens[0].used == 2);

  // A reservation whose ?X never becomes a drawn segment frees the token again.
  const char* erasing =
      "axiom: ?seed\n?seed(x, y, h) -> ?X(1)\n?X(found, id, delta) : found -> ε\n"
      "?X(found, id, delta) : !found -> F(delta) ?X(delta)\n";
  const dg::GrowthResult released = dg::grow(two_guides(1, {3}, erasing));
  CHECK(released.guides[1].seeds == 0);
  CHECK(released.tokens[0].free == 1);
  CHECK(released.tokens[0].used == 0);
}

TEST_CASE("values given to ?X travel with the message to the target's ?seed", "[growth]") {
  // A passes its level 7 through ?X; B draws one segment of that length.
  const char* rules =
      "axiom: ?seed(1)\n"
      "?seed(x, y, h, level) : level == 1 -> ?X(1, 7)\n"
      "?seed(x, y, h, level) : level != 1 -> F(level / 7)\n"
      "?X(found, id, delta, level) : found -> F(delta) cut\n"
      "?X(found, id, delta, level) : !found -> F(delta) ?X(delta, level)\n";
  dg::GrowthScene scene = two_guides(1, {3}, rules);
  const dg::GrowthResult result = dg::grow(scene);
  REQUIRE(result.guides[1].segments.size() == 1);
  CHECK(result.guides[1].received[0].values == std::vector<double>{7});
}

TEST_CASE("an L-system that grows forever stops at the derivation limit with a clear message", "[growth]") {
  dg::GrowthScene scene = two_guides(1, {3}, "axiom: ?seed\n?seed(x, y, h) -> A\nA -> f(0) A\n");
  scene.limits.max_steps = 200;
  CHECK_THROWS_WITH(dg::grow(scene), Catch::Contains("derivation limit") && Catch::Contains("guide 'A'"));
  dg::GrowthScene wide = two_guides(1, {3}, "axiom: ?seed\n?seed(x, y, h) -> A\nA -> [F(0.001)] A\n");
  wide.limits.max_elements = 500;
  CHECK_THROWS_WITH(dg::grow(wide), Catch::Contains("element limit"));
}

TEST_CASE("the palm tree grows through every link and stops when the tokens run out", "[growth]") {
  const dg::GrowthScene scene = palm();
  REQUIRE(scene.guides.size() == 9);
  const dg::GrowthResult result = dg::grow(scene);
  for (std::size_t l = 0; l < scene.links.size(); ++l) {
    INFO("link " << l);
    CHECK(result.tokens[l].used == scene.links[l].tokens);  // every token spent
    CHECK(result.tokens[l].free == 0);
  }
  for (std::size_t g = 0; g < scene.guides.size(); ++g) {
    INFO(scene.guides[g].name);
    CHECK(result.guides[g].seeds == 1);
    CHECK(result.guides[g].segments.size() >= 10);
    for (const dg::GridSegment& s : result.guides[g].segments)
      CHECK(dg::point_in_polygon(0.5 * (s.a + s.b), scene.guides[g].polygon));
  }
  // The trunk reaches the crown: the top trunk guide's last segment ends beyond its top edge.
  const dg::GrowthResult again = dg::grow(scene);
  CHECK(same_segments(again.guides[5].segments, result.guides[5].segments));  // same seed, same result
}

TEST_CASE("a mass-spring edit regrows only the moved guide and its dependents", "[growth]") {
  dg::GrowthScene scene = palm();
  const dg::GrowthResult before = dg::grow(scene);
  // Drag the middle trunk guide's right top corner; trunk1 is pinned (the palm's root).
  dg::GuideEdit drag;
  drag.kind = dg::GuideEdit::Kind::MoveVertex;
  drag.guide = 1;
  drag.vertex = 4;
  drag.offset = scene.guides[1].polygon[4] + dg::Vec2(0.25, 0.05);
  const std::vector<std::size_t> changed = dg::apply_guide_edit(scene, drag);
  CHECK(std::find(changed.begin(), changed.end(), 1) != changed.end());
  const std::vector<std::size_t> regrown = dg::dependent_guides(scene, changed);
  const dg::GrowthResult after = dg::regrow(scene, before, changed);
  CHECK(after.regrown_guides == regrown.size());
  CHECK(after.regrown_guides < scene.guides.size());
  const dg::GrowthResult fresh = dg::grow(scene);
  for (std::size_t g = 0; g < scene.guides.size(); ++g) {
    INFO(scene.guides[g].name);
    const bool dependent = std::find(regrown.begin(), regrown.end(), g) != regrown.end();
    if (!dependent) CHECK(same_segments(after.guides[g].segments, before.guides[g].segments));
    CHECK(same_segments(after.guides[g].segments, fresh.guides[g].segments));  // incremental == from scratch
  }
  CHECK_FALSE(same_segments(after.guides[1].segments, before.guides[1].segments));

  // Moving one leaf (no other guide depends on it) regrows just that leaf.
  dg::GuideEdit shift;
  shift.guide = 4;
  shift.offset = {0.05, 0.1};
  const std::vector<std::size_t> leaf = dg::apply_guide_edit(scene, shift);
  CHECK(dg::dependent_guides(scene, leaf) == std::vector<std::size_t>{4});
  const dg::GrowthResult leaf_only = dg::regrow(scene, fresh, leaf);
  CHECK(leaf_only.regrown_guides == 1);
  CHECK(same_segments(leaf_only.guides[4].segments, dg::grow(scene).guides[4].segments));
}

TEST_CASE("guide edits: snap shares an edge, scale and rotate keep the seeds inside", "[growth]") {
  dg::GrowthScene scene = two_guides(1, {3});
  dg::GuideEdit snap;
  snap.kind = dg::GuideEdit::Kind::Snap;
  snap.guide = 1;
  scene.guides[1].polygon = box(20, 5, 30, 15);  // moved away
  snap.edge = 0;
  snap.target = 0;
  snap.target_edge = 2;
  dg::apply_guide_edit(scene, snap);
  CHECK(scene.guides[1].polygon[0] == scene.guides[0].polygon[3]);
  CHECK(scene.guides[1].polygon[1] == scene.guides[0].polygon[2]);
  CHECK((scene.guides[1].polygon[2] - dg::Vec2(10, 20)).norm() < 1e-9);

  dg::GuideEdit rotate;
  rotate.kind = dg::GuideEdit::Kind::Rotate;
  rotate.guide = 0;
  rotate.angle_deg = 90;
  dg::apply_guide_edit(scene, rotate);
  CHECK((scene.guides[0].seeds[0].position - dg::Vec2(10, 3)).norm() < 1e-9);
  CHECK(scene.guides[0].seeds[0].heading_deg == Approx(180));
}

TEST_CASE("bad scenes name the problem", "[growth]") {
  const std::string guide = R"({"id": "A", "polygon": [[0,0],[1,0],[1,1],[0,1]], "lsystem": "w"})";
  const std::string lsystem = R"("lsystems": {"w": "axiom: F"})";
  CHECK(error_of("{" + lsystem + R"(, "guides": [)" + guide +
                 R"(], "links": [{"from": "A", "from_edge": 0, "to": "nope", "to_edge": 0}]})") ==
        "bad.json: links[0].to: unknown guide 'nope'");
  CHECK(error_of("{" + lsystem + R"(, "guides": [{"id": "B", "polygon": [[0,0],[1,1],[1,0],[0,1]]}]})") ==
        "bad.json: guide 'B': the polygon intersects itself");
  CHECK(error_of(R"({"guides": [)" + guide + "]}") == "bad.json: guides[0].lsystem: unknown L-system 'w'");
  CHECK(error_of("{" + lsystem + R"(, "guides": [)" + guide + R"(], "links": [{"from": "A", "from_edge": 9, "to": "A", "to_edge": 0}]})") ==
        "bad.json: links[0].from_edge: guide 'A' has no edge 9");
  CHECK(error_of("{\n\"guides\": [\n}") == "bad.json:3: column 1: malformed JSON");
  CHECK(error_of(R"({"lsystems": {"w": "axiom: F("}, "guides": [)" + guide + "]}").find("bad.json: lsystems.w:1") == 0);
}

TEST_CASE("the same seed gives the same growth, stochastic rules follow the seed", "[growth]") {
  const dg::GrowthScene streets =
      dg::read_growth_scene(std::string(DOCKGRAMMAR_SOURCE_DIR) + "/assets/scenes/streets.json");
  dg::GrowthOptions one;
  one.seed = 1;
  dg::GrowthOptions two;
  two.seed = 2;
  const dg::GrowthResult a = dg::grow(streets, one), b = dg::grow(streets, one), c = dg::grow(streets, two);
  bool all_same = true, any_different = false;
  for (std::size_t g = 0; g < streets.guides.size(); ++g) {
    all_same = all_same && same_segments(a.guides[g].segments, b.guides[g].segments);
    any_different = any_different || !same_segments(a.guides[g].segments, c.guides[g].segments);
  }
  CHECK(all_same);
  CHECK(any_different);  // the side streets are kept with probability 0.85
  CHECK(same_segments(a.guides[0].segments, c.guides[0].segments));  // the centre has no stochastic rule
}
