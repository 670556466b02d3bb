#include "synthesis/growth.h"

#include "geometry/errors.h"
#include "grammar/derivation.h"
#include "grammar/open_lsystem.h"
#include "geometry/random.h"
#include "synthesis/growth_queries.h"
#include "synthesis/growth_string.h"
#include "synthesis/segment2d.h"
#include "synthesis/turtle.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <tuple>
#include <unordered_set>

namespace dg {

namespace {

// A seed waiting to start: explicit (link unset) or received through `link`.
struct PendingSeed {
  int step = 0;
  std::size_t guide = 0;
  bool received = false;
  std::size_t order = 0;  // explicit: seed index; received: link index
  double t = 0;
  std::vector<double> values;

  auto key() const { return std::tie(step, received, order, t); }
};

// One seed's string while it grows, and its fresh queries waiting for answers.
struct SeedRun {
  GrowingString string;
  bool active = true;
  bool dirty = true;
  std::vector<PendingQuery> queries;
};

// Where a branch holding a reservation crossed the link's edge: the crossing ?X, the edge
// parameter and the values that travel with the message.
struct Crossing {
  std::size_t module = 0;
  double t = 0;
  std::vector<double> carried;
};

// A token of `link` reserved by a branch of run `run` of guide `guide` (§3.3.2): `holders` are
// the branch's modules that can still act (queries, or symbols with productions), followed
// through every rewrite; the token is used when one of them crosses the link's edge and is
// drawn, and freed when none is left.
struct Reservation {
  std::size_t guide = 0;
  std::size_t run = 0;
  std::size_t link = 0;
  std::vector<std::size_t> holders;
  std::optional<Crossing> crossing;
};

// One growing guide.
struct GuideRunner {
  const Guide* guide = nullptr;
  const LSystem* system = nullptr;
  std::unique_ptr<Rewriter> rewriter;
  std::unordered_set<std::string> rewritten_symbols;  // symbols with productions
  TurtleOptions turtle;
  std::unique_ptr<Random> random;
  SegmentGrid grid;
  GuideEnvironment environment;
  std::vector<SeedRun> runs;
  std::vector<ReceivedSeed> received;
  std::vector<std::size_t> provisional;  // grid ids of segments that ?X added in the last answer phase
  std::size_t laid_out = 0;              // live segments when the grid's cells were last laid out
  Vec2 low = Vec2::Zero(), high = Vec2::Zero();

  // Whether a fresh module can still change: a query, or a symbol with productions.
  bool growing(const Module& module) const {
    return is_query_symbol(module.symbol) || rewritten_symbols.count(module.symbol) > 0;
  }
};

[[noreturn]] void fail_guide(const Guide& guide, const std::string& problem) {
  throw InputError("guide '" + guide.name + "': " + problem);
}

Vec2 edge_point(const std::vector<Vec2>& polygon, std::size_t edge, double t) {
  const Vec2& a = polygon[edge];
  const Vec2& b = polygon[(edge + 1) % polygon.size()];
  return a + t * (b - a);
}

// Heading (degrees) of the inward normal of `edge`.
double inward_heading(const std::vector<Vec2>& polygon, std::size_t edge) {
  const Vec2 d = polygon[(edge + 1) % polygon.size()] - polygon[edge];
  const Vec2 left(-d.y(), d.x());
  const Vec2 inward = polygon_signed_area(polygon) > 0 ? left : Vec2(-left);
  return std::atan2(inward.y(), inward.x()) * 180.0 / std::numbers::pi;
}

class Growth {
 public:
  Growth(const GrowthScene& scene, const GrowthOptions& options, const std::vector<char>& grows)
      : scene_(scene), grows_(grows), guides_(scene.guides.size()), tokens_(scene.links.size()) {
    for (std::size_t g = 0; g < scene.guides.size(); ++g) {
      GuideRunner& runner = guides_[g];
      const Guide& guide = scene.guides[g];
      runner.guide = &guide;
      runner.random = std::make_unique<Random>(options.seed ^ (0x9E3779B97F4A7C15ull * (g + 1)));
      runner.low = runner.high = guide.polygon.front();
      for (const Vec2& v : guide.polygon) {
        runner.low = runner.low.cwiseMin(v);
        runner.high = runner.high.cwiseMax(v);
      }
      runner.environment.polygon = &guide.polygon;
      runner.environment.elements = &runner.grid;
      const Vec2 margin = 0.1 * (runner.high - runner.low);
      runner.grid.reset(runner.low - margin, runner.high + margin, 0, 0);
      if (!grows[g] || !guide.lsystem) continue;
      runner.system = &scene.lsystems[*guide.lsystem].system;
      runner.rewriter = std::make_unique<Rewriter>(*runner.system);
      for (const Production& production : runner.system->productions)
        runner.rewritten_symbols.insert(production.predecessor);
      try {
        runner.turtle = turtle_options(runner.system->turtle);
      } catch (const InputError& error) {
        fail_guide(guide, error.what());
      }
    }
    for (std::size_t l = 0; l < scene.links.size(); ++l) {
      const GuideLink& link = scene.links[l];
      if (!grows[link.from_guide]) continue;
      tokens_[l].free = link.tokens;
      const std::vector<Vec2>& polygon = scene.guides[link.from_guide].polygon;
      guides_[link.from_guide].environment.links.push_back(
          {polygon[link.from_edge], polygon[(link.from_edge + 1) % polygon.size()], l, link.from_edge});
    }
  }

  void schedule(PendingSeed seed) { pending_.push_back(std::move(seed)); }

  void run() {
    int step = 0;
    while (true) {
      start_pending(step);
      answer_all();
      const bool any_active = std::any_of(guides_.begin(), guides_.end(), [](const GuideRunner& runner) {
        return std::any_of(runner.runs.begin(), runner.runs.end(), [](const SeedRun& r) { return r.active; });
      });
      if (!any_active) {
        if (pending_.empty()) break;
        step = std::min_element(pending_.begin(), pending_.end(),
                                [](const PendingSeed& a, const PendingSeed& b) { return a.step < b.step; })->step;
        continue;
      }
      if (++step > scene_.limits.max_steps) too_many_steps();
      rewrite_all(step);
    }
    steps_ = step;
  }

  GrowthResult result(const GrowthResult* previous) const {
    GrowthResult result;
    result.steps = steps_;
    result.guides.resize(guides_.size());
    for (std::size_t g = 0; g < guides_.size(); ++g) {
      if (!grows_[g]) {
        result.guides[g] = previous->guides[g];
        continue;
      }
      ++result.regrown_guides;
      GuideGrowth& out = result.guides[g];
      for (const SeedRun& run : guides_[g].runs) run.string.collect(guides_[g].grid, out.segments, out.motifs);
      out.received = guides_[g].received;
      out.seeds = guides_[g].runs.size();
    }
    result.tokens = tokens_;
    for (std::size_t l = 0; l < scene_.links.size(); ++l)
      if (!grows_[scene_.links[l].from_guide]) result.tokens[l] = previous->tokens[l];
    return result;
  }

 private:
  void start_pending(int step) {
    std::vector<PendingSeed> now;
    for (auto it = pending_.begin(); it != pending_.end();) {
      if (it->step == step) {
        now.push_back(std::move(*it));
        it = pending_.erase(it);
      } else {
        ++it;
      }
    }
    std::sort(now.begin(), now.end(), [](const PendingSeed& a, const PendingSeed& b) { return a.key() < b.key(); });
    for (PendingSeed& seed : now) start(seed);
  }

  void start(PendingSeed& seed) {
    GuideRunner& runner = guides_[seed.guide];
    const Guide& guide = *runner.guide;
    SeedStart start;
    if (seed.received) {
      const GuideLink& link = scene_.links[seed.order];
      runner.received.push_back({seed.order, seed.t, seed.values, seed.step});
      start.pose.position = edge_point(guide.polygon, link.to_edge, 1 - seed.t);
      start.pose.heading_deg = inward_heading(guide.polygon, link.to_edge) + link.angle_deg;
    } else {
      const GuideSeed& explicit_seed = guide.seeds[seed.order];
      start.pose.position = explicit_seed.position;
      start.pose.heading_deg = explicit_seed.heading_deg;
    }
    start.values = std::move(seed.values);
    if (!runner.system) return;  // a guide without L-system receives but does not grow
    start.element_id = static_cast<double>(runner.runs.size());
    runner.runs.push_back({GrowingString(runner.system->axiom, std::move(start)), true, true, {}});
  }

  void answer_all() {
    std::size_t elements = 0;
    for (std::size_t g = 0; g < guides_.size(); ++g) {
      GuideRunner& runner = guides_[g];
      if (std::any_of(runner.runs.begin(), runner.runs.end(), [](const SeedRun& r) { return r.dirty; })) {
        try {
          answer_guide(g);
        } catch (const InputError& error) {
          fail_guide(*runner.guide, error.what());
        }
      }
      for (const SeedRun& run : runner.runs) elements += run.string.elements();
    }
    if (elements > scene_.limits.max_elements)
      throw LimitError("growth exceeds " + std::to_string(scene_.limits.max_elements) +
                       " elements (element limit); use fewer tokens or seeds, or rules that stop");
  }

  // Draws the changed strings of guide g, collapses what cannot change any more, and answers
  // the fresh queries in string order, seeds in start order.
  void answer_guide(std::size_t g) {
    GuideRunner& runner = guides_[g];
    for (std::size_t id : runner.provisional) runner.grid.remove(id);
    runner.provisional.clear();
    const GrowthCanvas canvas{&runner.guide->polygon, &runner.turtle, &runner.grid};
    const auto growing = [&runner](const Module& module) { return runner.growing(module); };
    for (std::size_t r = 0; r < runner.runs.size(); ++r) {
      SeedRun& run = runner.runs[r];
      if (!run.dirty) continue;
      run.queries = run.string.interpret(canvas);
      const std::vector<std::size_t> renumber = run.string.collapse(growing);
      for (PendingQuery& query : run.queries) query.module = renumber[query.module];
      for (Reservation& reservation : reservations_)
        if (reservation.guide == g && reservation.run == r)
          for (std::size_t& holder : reservation.holders) holder = renumber[holder];
    }
    if (runner.grid.live() > 4 * runner.laid_out + 256) {  // re-lay the cells for the grown count
      double length_sum = 0;
      for (std::size_t id = 0; id < runner.grid.size(); ++id) length_sum += (runner.grid[id].b - runner.grid[id].a).norm();
      runner.grid.relayout(runner.grid.size() ? 0.5 * length_sum / static_cast<double>(runner.grid.size()) : 0);
      runner.laid_out = runner.grid.live();
    }
    const std::size_t before = runner.grid.size();
    for (std::size_t r = 0; r < runner.runs.size(); ++r) {
      SeedRun& run = runner.runs[r];
      for (const PendingQuery& query : run.queries) {
        runner.environment.available = [&](std::size_t link) { return link_available(g, r, query.module, link); };
        const QueryOutcome outcome =
            answer_query(run.string.modules()[query.module], query.pose, runner.environment, run.string.start());
        if (outcome.selected_link) select(g, r, query.module, *outcome.selected_link);
        if (outcome.crossing) cross(g, r, query.module, *outcome.crossing);
      }
      run.queries.clear();
      run.string.answered();
      run.dirty = false;
    }
    runner.environment.available = nullptr;
    for (std::size_t id = before; id < runner.grid.size(); ++id) runner.provisional.push_back(id);
  }

  // The reservation of `link` that module `module` of run r of guide g holds, or nullptr.
  Reservation* held(std::size_t g, std::size_t r, std::size_t module, std::size_t link) {
    for (Reservation& reservation : reservations_)
      if (reservation.guide == g && reservation.run == r && reservation.link == link &&
          std::find(reservation.holders.begin(), reservation.holders.end(), module) != reservation.holders.end())
        return &reservation;
    return nullptr;
  }

  // A link query may select a link without tokens (it only steers), one with a free token, or
  // one its own branch reserved; links whose tokens others hold or used are not seen.
  bool link_available(std::size_t g, std::size_t r, std::size_t module, std::size_t link) {
    return scene_.links[link].tokens == 0 || tokens_[link].free > 0 || held(g, r, module, link);
  }

  Reservation& reserve(std::size_t g, std::size_t r, std::size_t module, std::size_t link) {
    --tokens_[link].free;
    ++tokens_[link].reserved;
    reservations_.push_back({g, r, link, {module}, std::nullopt});
    return reservations_.back();
  }

  // A link query of module `module` selected `link` as its target: its branch reserves a token.
  void select(std::size_t g, std::size_t r, std::size_t module, std::size_t link) {
    if (tokens_[link].free > 0 && !held(g, r, module, link)) reserve(g, r, module, link);
  }

  // The ?X at `module` crossed an edge holding links: it uses the tokens its branch reserved
  // there and takes a free token of the other links on that edge.
  void cross(std::size_t g, std::size_t r, std::size_t module, const EdgeCrossing& crossing) {
    for (std::size_t link : crossing.links) {
      Reservation* reservation = held(g, r, module, link);
      if (!reservation && tokens_[link].free > 0) reservation = &reserve(g, r, module, link);
      if (reservation) reservation->crossing = Crossing{module, crossing.t, crossing.carried};
    }
  }

  void rewrite_all(int step) {
    std::vector<Module> next;
    std::vector<std::size_t> origins;
    std::vector<char> fresh;
    for (std::size_t g = 0; g < guides_.size(); ++g) {
      GuideRunner& runner = guides_[g];
      for (std::size_t r = 0; r < runner.runs.size(); ++r) {
        SeedRun& run = runner.runs[r];
        if (!run.active) continue;
        next.clear();
        origins.clear();
        fresh.clear();
        bool rewrote = false;
        try {
          rewrote = runner.rewriter->step(run.string.modules(), *runner.random, next, &origins, &fresh,
                                          scene_.limits.max_modules, step);
        } catch (const InputError& error) {
          fail_guide(*runner.guide, error.what());
        }
        if (rewrote) apply_cuts(next, &origins, &fresh);
        run.string.replace(next, fresh, origins, runner.grid);
        run.dirty = rewrote;
        run.active = rewrote;
        resolve(g, r, origins, step);
      }
    }
  }

  // Follows the reservations of run r of guide g through its rewrite: a crossing is used when
  // the crossing ?X became a drawn segment (the target guide gets a seed); otherwise the
  // holders move to their descendants that can still act, and the token is freed when none is
  // left (the branch was erased or stopped).
  void resolve(std::size_t g, std::size_t r, const std::vector<std::size_t>& origins, int step) {
    const GuideRunner& runner = guides_[g];
    const GrowingString& string = runner.runs[r].string;
    auto descendants = [&](std::size_t module) {
      const auto [first, last] = std::equal_range(origins.begin(), origins.end(), module);
      return std::pair{static_cast<std::size_t>(first - origins.begin()), static_cast<std::size_t>(last - origins.begin())};
    };
    for (auto it = reservations_.begin(); it != reservations_.end();) {
      if (it->guide != g || it->run != r) {
        ++it;
        continue;
      }
      TokenState& token = tokens_[it->link];
      if (it->crossing) {
        bool reached = false;
        const auto [first, last] = descendants(it->crossing->module);
        for (std::size_t k = first; k < last && !reached; ++k)
          reached = string.fresh()[k] && std::find(runner.turtle.draw_symbols.begin(), runner.turtle.draw_symbols.end(),
                                                   string.modules()[k].symbol) != runner.turtle.draw_symbols.end();
        if (reached) {
          --token.reserved;
          ++token.used;
          schedule({step, scene_.links[it->link].to_guide, true, it->link, it->crossing->t, std::move(it->crossing->carried)});
          it = reservations_.erase(it);
          continue;
        }
        it->crossing.reset();
      }
      std::vector<std::size_t> holders;
      for (std::size_t holder : it->holders) {
        const auto [first, last] = descendants(holder);
        for (std::size_t k = first; k < last; ++k)
          if (string.fresh()[k] && runner.growing(string.modules()[k])) holders.push_back(k);
      }
      it->holders = std::move(holders);
      if (it->holders.empty()) {
        --token.reserved;
        ++token.free;
        it = reservations_.erase(it);
      } else {
        ++it;
      }
    }
  }

  [[noreturn]] void too_many_steps() const {
    std::string growing;
    for (const GuideRunner& runner : guides_)
      if (std::any_of(runner.runs.begin(), runner.runs.end(), [](const SeedRun& r) { return r.active; })) {
        growing = runner.guide->name;
        break;
      }
    throw LimitError("growth still running after " + std::to_string(scene_.limits.max_steps) +
                     " steps (derivation limit): the L-system of guide '" + growing +
                     "' keeps rewriting; check its rules for endless growth or raise the step limit");
  }

  const GrowthScene& scene_;
  const std::vector<char>& grows_;
  std::vector<GuideRunner> guides_;
  std::vector<TokenState> tokens_;
  std::vector<PendingSeed> pending_;
  std::vector<Reservation> reservations_;
  int steps_ = 0;
};

}  // namespace

std::size_t GrowthResult::elements() const {
  std::size_t count = 0;
  for (const GuideGrowth& guide : guides) count += guide.segments.size() + guide.motifs.size();
  return count;
}

void check_growth_scene(const GrowthScene& scene) {
  for (const Guide& guide : scene.guides) {
    if (guide.polygon.size() < 3) fail_guide(guide, "a guide polygon needs at least 3 vertices");
    for (const Vec2& v : guide.polygon)
      if (!v.allFinite()) fail_guide(guide, "a vertex is not a finite number");
    if (polygon_self_intersects(guide.polygon)) fail_guide(guide, "the polygon intersects itself");
    if (guide.lsystem && *guide.lsystem >= scene.lsystems.size()) fail_guide(guide, "unknown L-system");
  }
  for (std::size_t l = 0; l < scene.links.size(); ++l) {
    const GuideLink& link = scene.links[l];
    const std::string name = "link " + std::to_string(l);
    if (link.from_guide >= scene.guides.size() || link.to_guide >= scene.guides.size())
      throw InputError(name + ": unknown guide");
    if (link.from_edge >= scene.guides[link.from_guide].polygon.size())
      throw InputError(name + ": guide '" + scene.guides[link.from_guide].name + "' has no edge " +
                       std::to_string(link.from_edge));
    if (link.to_edge >= scene.guides[link.to_guide].polygon.size())
      throw InputError(name + ": guide '" + scene.guides[link.to_guide].name + "' has no edge " +
                       std::to_string(link.to_edge));
    if (link.tokens < 0) throw InputError(name + ": tokens must be >= 0");
  }
}

GrowthResult grow(const GrowthScene& scene, const GrowthOptions& options) {
  check_growth_scene(scene);
  const std::vector<char> all(scene.guides.size(), 1);
  Growth growth(scene, options, all);
  for (std::size_t g = 0; g < scene.guides.size(); ++g)
    for (std::size_t s = 0; s < scene.guides[g].seeds.size(); ++s)
      growth.schedule({0, g, false, s, 0, scene.guides[g].seeds[s].parameters});
  growth.run();
  return growth.result(nullptr);
}

std::vector<std::size_t> dependent_guides(const GrowthScene& scene, const std::vector<std::size_t>& changed) {
  std::vector<char> reached(scene.guides.size(), 0);
  std::vector<std::size_t> stack;
  for (std::size_t g : changed)
    if (g < reached.size() && !reached[g]) {
      reached[g] = 1;
      stack.push_back(g);
    }
  while (!stack.empty()) {
    const std::size_t g = stack.back();
    stack.pop_back();
    for (const GuideLink& link : scene.links)
      if (link.from_guide == g && !reached[link.to_guide]) {
        reached[link.to_guide] = 1;
        stack.push_back(link.to_guide);
      }
  }
  std::vector<std::size_t> guides;
  for (std::size_t g = 0; g < reached.size(); ++g)
    if (reached[g]) guides.push_back(g);
  return guides;
}

GrowthResult regrow(const GrowthScene& scene, const GrowthResult& previous, const std::vector<std::size_t>& changed,
                    const GrowthOptions& options) {
  check_growth_scene(scene);
  if (previous.guides.size() != scene.guides.size() || previous.tokens.size() != scene.links.size())
    throw InputError("regrow: the previous growth belongs to another scene");
  std::vector<char> grows(scene.guides.size(), 0);
  for (std::size_t g : dependent_guides(scene, changed)) grows[g] = 1;
  Growth growth(scene, options, grows);
  for (std::size_t g = 0; g < scene.guides.size(); ++g) {
    if (!grows[g]) continue;
    for (std::size_t s = 0; s < scene.guides[g].seeds.size(); ++s)
      growth.schedule({0, g, false, s, 0, scene.guides[g].seeds[s].parameters});
    for (const ReceivedSeed& seed : previous.guides[g].received)
      if (!grows[scene.links[seed.link].from_guide]) growth.schedule({seed.step, g, true, seed.link, seed.t, seed.values});
  }
  growth.run();
  return growth.result(&previous);
}

}  // namespace dg
