// Bench of guided growth (Beneš et al. 2011 reports 45 s for 85,000 elements): a street-like
// grid grows in square guides sized for about 1k, 10k and 100k elements. Every drawn segment
// is preceded by one ?X collision query against all elements of its guide (uniform grid).
// Two layouts: one guide, and a 2 x 2 block of guides linked in a chain (messages pass the
// arterial on). Prints one line per scene: layout, elements, collision queries, steps, seconds;
// then the time of an incremental regrowth after moving the last guide of the chain.
// Usage: dockgrammar-bench-growth [--quick]

#include "geometry/stopwatch.h"
#include "grammar/lsystem_text.h"
#include "geometry/random.h"
#include "synthesis/growth.h"
#include "synthesis/guide_edit.h"

#include <fmt/core.h>

#include <cmath>
#include <string>

namespace {

// The street grid of assets/scenes/streets.json (without the random gaps): the arterial sends
// side streets every 5 segments, which send streets again; streets stop where they meet.
const char* grid_rules =
    "axiom: ?seed\n"
    "?seed(x, y, h) -> ?X(0.05, 0, 0)\n"
    "?seed(x, y, h, n, level) -> ?X(0.05, 0, 0)\n"
    "?X(found, id, delta, n, level) : found -> F(delta) cut\n"
    "?X(found, id, delta, n, level) : !found && level < 2 && n > 0 && n - 5*floor(n/5) == 0 -> "
    "F(delta) [+(90) ?X(delta, 0, level+1)] [-(90) ?X(delta, 0, level+1)] ?X(delta, n+1, level)\n"
    "?X(found, id, delta, n, level) : !found && (level >= 2 || n == 0 || n - 5*floor(n/5) != 0) -> "
    "F(delta) ?X(delta, n+1, level)\n";

dg::GrowthScene one_guide(double side) {
  dg::GrowthScene scene;
  scene.lsystems.push_back({"grid", dg::parse_lsystem_text(grid_rules, "grid.ls")});
  dg::Guide guide{"square", {{0, 0}, {side, 0}, {side, side}, {0, side}}, 0, {}};
  guide.seeds.push_back({{side / 2 + 0.0123, 0}, 90, {}});
  scene.guides.push_back(guide);
  scene.limits.max_steps = 100000;
  return scene;
}

// Four squares of side/2 in a chain: bottom-left -> top-left -> top-right -> bottom-right,
// each link on the shared edge with one token.
dg::GrowthScene chain(double side) {
  dg::GrowthScene scene;
  scene.lsystems.push_back({"grid", dg::parse_lsystem_text(grid_rules, "grid.ls")});
  const double h = side / 2;
  auto square = [&](const std::string& name, double x, double y) {
    return dg::Guide{name, {{x, y}, {x + h, y}, {x + h, y + h}, {x, y + h}}, 0, {}};
  };
  scene.guides.push_back(square("a", 0, 0));
  scene.guides.push_back(square("b", 0, h));
  scene.guides.push_back(square("c", h, h));
  scene.guides.push_back(square("d", h, 0));
  scene.guides[0].seeds.push_back({{h / 2 + 0.0123, 0}, 90, {}});
  scene.links.push_back({0, 2, 1, 0, 1, 0});  // a top -> b bottom
  scene.links.push_back({1, 1, 2, 3, 1, 0});  // b right -> c left
  scene.links.push_back({2, 0, 3, 2, 1, 0});  // c bottom -> d top
  scene.limits.max_steps = 100000;
  return scene;
}

// The collision queries alone: the grown segments in one grid, then one ?X-like test per
// element (a segment of 0.05 from a random point of the guide in a random direction).
void time_collisions(const dg::GrowthScene& scene, const dg::GrowthResult& result) {
  dg::Stopwatch clock;
  dg::SegmentGrid grid;
  const dg::Vec2 high = scene.guides[0].polygon[2];
  std::size_t count = 0;
  for (const dg::GuideGrowth& guide : result.guides) count += guide.segments.size();
  grid.reset({0, 0}, high, count, 0.025);
  for (const dg::GuideGrowth& guide : result.guides)
    for (const dg::GridSegment& segment : guide.segments) grid.insert(segment);
  const double build_s = clock.lap();
  dg::Random random(3);
  std::size_t hits = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const dg::Vec2 p(random.uniform(0, high.x()), random.uniform(0, high.y()));
    const double angle = random.uniform(0, 6.283185307179586);
    hits += grid.first_hit(p, p + 0.05 * dg::Vec2(std::cos(angle), std::sin(angle)), 1e-6).has_value();
  }
  fmt::print("{:<10} grid of {} segments built in {:.3f} s; {} collision queries in {:.3f} s ({} hits)\n", "", count,
             build_s, count, clock.lap(), hits);
}

void run(const std::string& layout, const dg::GrowthScene& scene, bool edit) {
  dg::Stopwatch clock;
  const dg::GrowthResult result = dg::grow(scene);
  const double seconds = clock.lap();
  std::size_t queries = 0;
  for (const dg::GuideGrowth& guide : result.guides) queries += guide.segments.size();
  fmt::print("{:<10} {:>8} elements  {:>8} collision queries  {:>5} steps  {:>8.3f} s  ({:.2f} us per element)\n",
             layout, result.elements(), queries, result.steps, seconds, 1e6 * seconds / std::max<std::size_t>(1, result.elements()));
  if (!edit) {
    time_collisions(scene, result);
    return;
  }
  dg::GrowthScene edited = scene;
  dg::GuideEdit move;
  move.guide = edited.guides.size() - 1;
  move.kind = dg::GuideEdit::Kind::Rotate;
  move.angle_deg = 3;
  const auto changed = dg::apply_guide_edit(edited, move);
  dg::Stopwatch again;
  const dg::GrowthResult regrown = dg::regrow(edited, result, changed);
  const double regrow_s = again.lap();
  dg::Stopwatch full;
  dg::grow(edited);
  fmt::print("{:<10} regrow of {} of {} guides after a rotation: {:.3f} s (from scratch {:.3f} s)\n", "", regrown.regrown_guides,
             edited.guides.size(), regrow_s, full.lap());
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::string(argv[1]) == "--quick";
  // About 90 segments per unit of area: sides 3.33, 10.5 and 33.3 give about 1k, 10k and 100k.
  for (double side : {3.33, 10.5, 33.3}) {
    if (quick && side > 10) continue;
    run("one guide", one_guide(side), false);
    run("chain of 4", chain(side), true);
  }
  return 0;
}
