#include "synthesis/growth.h"

#include "geometry/errors.h"
#include "grammar/derivation.h"
#include "grammar/open_lsystem.h"
#include "grammar/random.h"
#include "synthesis/growth_queries.h"
#include "synthesis/segment2d.h"
#include "synthesis/turtle.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <tuple>

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

// A kept element of a run: the module that drew it and its index in the guide's grid (segments)
// or its shape (motifs).
struct DrawnSegment {
  std::size_t module = 0;
  std::size_t id = 0;
};
struct DrawnMotif {
  std::size_t module = 0;
  Path2d path;
};

// One seed's string while it grows, with what its last interpretation found: kept elements in
// module order, and for every `[` its matching `]` and the pose before it, so that unchanged
// branches at unchanged poses are not walked again.
struct SeedRun {
  SeedStart start;
  std::vector<Module> modules;
  std::vector<char> fresh;
  std::vector<std::size_t> origins;  // module -> index before the last rewrite (empty: new run)
  bool active = true;
  bool dirty = true;
  std::vector<DrawnSegment> segments;
  std::vector<DrawnMotif> motifs;
  std::vector<std::size_t> frozen_segments;  // grid ids of elements of branches taken out (freeze)
  std::vector<Path2d> frozen_motifs;
  std::vector<std::size_t> match;     // `[` -> its `]` (npos elsewhere)
  std::vector<TurtlePose> poses;      // `[` -> the pose before it
  std::vector<std::pair<std::size_t, TurtlePose>> queries;  // fresh query modules and where they are
};

// A token reserved by the ?X at `module` of run `run` of guide `guide`.
struct Reservation {
  std::size_t guide = 0;
  std::size_t run = 0;
  std::size_t module = 0;
  std::size_t link = 0;
  double t = 0;
  std::vector<double> carried;
};

// One growing guide.
struct GuideRunner {
  const Guide* guide = nullptr;
  const LSystem* system = nullptr;
  std::unique_ptr<Rewriter> rewriter;
  TurtleOptions turtle;
  std::unique_ptr<Random> random;
  SegmentGrid grid;
  GuideEnvironment environment;
  std::vector<SeedRun> runs;
  std::vector<ReceivedSeed> received;
  std::vector<std::size_t> provisional;  // grid ids of segments that ?X added in the last answer phase
  std::size_t laid_out = 0;              // live segments when the grid's cells were last laid out
  Vec2 low = Vec2::Zero(), high = Vec2::Zero();
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
      for (const SeedRun& run : guides_[g].runs) {
        for (std::size_t id : run.frozen_segments) out.segments.push_back(guides_[g].grid[id]);
        for (const DrawnSegment& segment : run.segments) out.segments.push_back(guides_[g].grid[segment.id]);
        out.motifs.insert(out.motifs.end(), run.frozen_motifs.begin(), run.frozen_motifs.end());
        for (const DrawnMotif& motif : run.motifs) out.motifs.push_back(motif.path);
      }
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
    SeedRun run;
    run.start = std::move(start);
    run.modules = runner.system->axiom;
    run.fresh.assign(run.modules.size(), 1);
    apply_cuts(run.modules, nullptr, &run.fresh);
    runner.runs.push_back(std::move(run));
  }

  // Walks the run's string and updates its kept elements in the guide's grid. A `[` that was
  // copied unchanged together with its whole branch, at the same pose as before, is skipped:
  // its elements are taken over (drawn by the same modules at the same poses, they are equal).
  void interpret(GuideRunner& runner, SeedRun& run) {
    constexpr std::size_t none = static_cast<std::size_t>(-1);
    const std::vector<Vec2>& polygon = runner.guide->polygon;
    const std::size_t n = run.modules.size();
    std::vector<DrawnSegment> old_segments = std::move(run.segments);
    std::vector<DrawnMotif> old_motifs = std::move(run.motifs);
    std::vector<std::size_t> old_match = std::move(run.match);
    std::vector<TurtlePose> old_poses = std::move(run.poses);
    std::vector<char> reused(old_segments.size(), 0);
    run.segments.clear();
    run.motifs.clear();
    run.queries.clear();
    run.match.assign(n, none);
    run.poses.resize(n);
    std::vector<std::size_t> fresh_before(n + 1, 0);  // fresh modules before index k
    for (std::size_t k = 0; k < n; ++k) fresh_before[k + 1] = fresh_before[k] + (run.fresh[k] ? 1 : 0);
    std::vector<std::size_t> open;  // `[` not closed yet
    for (std::size_t k = 0; k < n; ++k) {
      const std::string& symbol = run.modules[k].symbol;
      if (symbol == "[") {
        open.push_back(k);
      } else if (symbol == "]" && !open.empty()) {
        run.match[open.back()] = k;
        open.pop_back();
      }
    }
    auto by_module = [](const auto& element, std::size_t module) { return element.module < module; };

    TurtleVisitor visitor;
    visitor.branch = [&](std::size_t k, const TurtlePose& pose) -> std::size_t {
      run.poses[k] = pose;
      if (!run.origins.empty() && !run.fresh[k]) {
        const std::size_t i = run.origins[k];
        const std::size_t j = i < old_match.size() ? old_match[i] : none;
        if (j != none && k + (j - i) < n && run.origins[k + (j - i)] == j && fresh_before[k + (j - i) + 1] == fresh_before[k] &&
            old_poses[i].position == pose.position && old_poses[i].heading_deg == pose.heading_deg &&
            old_poses[i].scale == pose.scale) {
          const std::size_t shift = k - i;  // new index = old index + shift inside the branch
          auto first = std::lower_bound(old_segments.begin(), old_segments.end(), i, by_module);
          for (auto it = first; it != old_segments.end() && it->module <= j; ++it) {
            run.segments.push_back({it->module + shift, it->id});
            reused[static_cast<std::size_t>(it - old_segments.begin())] = 1;
          }
          auto motif = std::lower_bound(old_motifs.begin(), old_motifs.end(), i, by_module);
          for (; motif != old_motifs.end() && motif->module <= j; ++motif)
            run.motifs.push_back({motif->module + shift, std::move(motif->path)});
          for (std::size_t m = i; m <= j; ++m)
            if (old_match[m] != none) run.poses[m + shift] = old_poses[m];
          return k + (j - i) + 1;
        }
      }
      return k;
    };
    // A copied drawing module that draws exactly its old segment keeps it (old segments are in
    // module order and origins grow with k, so one cursor finds them).
    std::size_t cursor = 0;
    visitor.segment = [&](std::size_t k, const Vec2& from, const Vec2& to) {
      if (!run.origins.empty() && !run.fresh[k]) {
        const std::size_t i = run.origins[k];
        while (cursor < old_segments.size() && old_segments[cursor].module < i) ++cursor;
        if (cursor < old_segments.size() && old_segments[cursor].module == i && !reused[cursor]) {
          const GridSegment& old = runner.grid[old_segments[cursor].id];
          if (old.a == from && old.b == to) {
            run.segments.push_back({k, old_segments[cursor].id});
            reused[cursor] = 1;
            return;
          }
        }
      }
      if (point_in_polygon(0.5 * (from + to), polygon))
        run.segments.push_back({k, runner.grid.insert({from, to, run.start.element_id})});
    };
    visitor.motif = [&](std::size_t k, const Path2d& motif, const TurtlePose& pose, double size) {
      if (point_in_polygon(pose.position, polygon)) run.motifs.push_back({k, place_motif(motif, pose, size)});
    };
    visitor.other = [&](std::size_t k, const TurtlePose& pose) -> double {
      const Module& module = run.modules[k];
      if (!is_query_symbol(module.symbol)) return 0;
      if (run.fresh[k]) run.queries.emplace_back(k, pose);
      return is_collision_query(module.symbol) ? collision_query_length(module, !run.fresh[k], pose.scale) : 0;
    };
    walk_turtle(run.modules, runner.turtle, run.start.pose, visitor);
    for (std::size_t e = 0; e < old_segments.size(); ++e)
      if (!reused[e]) runner.grid.remove(old_segments[e].id);
  }

  // Takes finished branches out of the string: a closed `[...]` whose modules were all copied
  // unchanged by the last step (so no production applies to any of them, ever: their
  // parameters are fixed) and before which no new module stands in any enclosing branch (so no
  // later `cut` can reach it). Such a branch leaves the turtle where it found it, so the rest of
  // the string is interpreted exactly as before; its elements stay in the grid. This keeps the
  // work of a step proportional to the growing part of the string.
  void freeze(SeedRun& run) {
    constexpr std::size_t none = static_cast<std::size_t>(-1);
    const std::size_t n = run.modules.size();
    if (run.origins.empty()) return;  // a new run: everything is fresh
    std::vector<char> remove(n, 0);
    std::vector<char> live_before;  // per open `[`: a fresh module stood before it (inherited)
    bool live = false;
    std::size_t removed = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const std::string& symbol = run.modules[k].symbol;
      if (symbol == "[") {
        const std::size_t end = run.match[k];
        if (!live && end != none) {
          bool all_copied = true;
          for (std::size_t m = k; m <= end && all_copied; ++m) all_copied = !run.fresh[m];
          if (all_copied) {
            std::fill(remove.begin() + static_cast<std::ptrdiff_t>(k), remove.begin() + static_cast<std::ptrdiff_t>(end) + 1, 1);
            removed += end - k + 1;
            k = end;
            continue;
          }
        }
        live_before.push_back(live);
      } else if (symbol == "]" && !live_before.empty()) {
        live = live_before.back();
        live_before.pop_back();
        continue;
      }
      live = live || run.fresh[k];
    }
    if (removed == 0) return;
    std::vector<std::size_t> renumber(n, none);
    std::size_t kept = 0;
    for (std::size_t k = 0; k < n; ++k)
      if (!remove[k]) renumber[k] = kept++;
    std::size_t write = 0;
    for (const DrawnSegment& segment : run.segments) {
      if (remove[segment.module]) {
        run.frozen_segments.push_back(segment.id);
      } else {
        run.segments[write++] = {renumber[segment.module], segment.id};
      }
    }
    run.segments.resize(write);
    write = 0;
    for (DrawnMotif& motif : run.motifs) {
      if (remove[motif.module]) {
        run.frozen_motifs.push_back(std::move(motif.path));
      } else {
        run.motifs[write++] = {renumber[motif.module], std::move(motif.path)};
      }
    }
    run.motifs.resize(write);
    for (auto& query : run.queries) query.first = renumber[query.first];
    std::vector<Module> modules;
    std::vector<char> fresh;
    std::vector<std::size_t> match;
    std::vector<TurtlePose> poses;
    modules.reserve(kept);
    for (std::size_t k = 0; k < n; ++k) {
      if (remove[k]) continue;
      modules.push_back(std::move(run.modules[k]));
      fresh.push_back(run.fresh[k]);
      match.push_back(run.match[k] == none ? none : renumber[run.match[k]]);
      poses.push_back(run.poses[k]);
    }
    run.modules = std::move(modules);
    run.fresh = std::move(fresh);
    run.match = std::move(match);
    run.poses = std::move(poses);
  }

  void answer_all() {
    std::size_t elements = 0;
    for (std::size_t g = 0; g < guides_.size(); ++g) {
      GuideRunner& runner = guides_[g];
      if (std::any_of(runner.runs.begin(), runner.runs.end(), [](const SeedRun& r) { return r.dirty; })) {
        try {
          answer_guide(runner);
        } catch (const InputError& error) {
          fail_guide(*runner.guide, error.what());
        }
      }
      for (const SeedRun& run : runner.runs)
        elements += run.segments.size() + run.motifs.size() + run.frozen_segments.size() + run.frozen_motifs.size();
    }
    if (elements > scene_.limits.max_elements)
      throw LimitError("growth exceeds " + std::to_string(scene_.limits.max_elements) +
                       " elements (element limit); use fewer tokens or seeds, or rules that stop");
  }

  void answer_guide(GuideRunner& runner) {
    for (std::size_t id : runner.provisional) runner.grid.remove(id);
    runner.provisional.clear();
    for (SeedRun& run : runner.runs)
      if (run.dirty) {
        interpret(runner, run);
        freeze(run);
      }
    if (runner.grid.live() > 4 * runner.laid_out + 256) {  // re-lay the cells for the grown count
      double length_sum = 0;
      std::size_t count = 0;
      for (std::size_t id = 0; id < runner.grid.size(); ++id) {
        length_sum += (runner.grid[id].b - runner.grid[id].a).norm();
        ++count;
      }
      runner.grid.relayout(count ? 0.5 * length_sum / count : 0);
      runner.laid_out = runner.grid.live();
    }
    const std::size_t before = runner.grid.size();
    for (std::size_t r = 0; r < runner.runs.size(); ++r) {
      SeedRun& run = runner.runs[r];
      for (const auto& [index, pose] : run.queries) {
        const auto crossing = answer_query(run.modules[index], pose, runner.environment, run.start);
        if (crossing) reserve(runner, r, index, *crossing);
      }
      run.queries.clear();
      std::fill(run.fresh.begin(), run.fresh.end(), 0);
      run.dirty = false;
    }
    for (std::size_t id = before; id < runner.grid.size(); ++id) runner.provisional.push_back(id);
  }

  void reserve(GuideRunner& runner, std::size_t run, std::size_t module, const EdgeCrossing& crossing) {
    for (std::size_t link : crossing.links)
      if (tokens_[link].free > 0) {
        --tokens_[link].free;
        ++tokens_[link].reserved;
        reservations_.push_back({static_cast<std::size_t>(&runner - guides_.data()), run, module, link, crossing.t,
                                 crossing.carried});
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
          rewrote = runner.rewriter->step(run.modules, *runner.random, next, &origins, &fresh,
                                          scene_.limits.max_modules, step);
        } catch (const InputError& error) {
          fail_guide(*runner.guide, error.what());
        }
        if (rewrote) {
          apply_cuts(next, &origins, &fresh);
          run.modules.swap(next);
          run.fresh.swap(fresh);
          run.origins = origins;
          run.dirty = true;
        } else {
          run.modules.swap(next);  // unchanged, but moved by the rewriter
          run.active = false;
        }
        resolve(g, r, rewrote, origins, step);
      }
    }
  }

  // Settles the reservations of run r of guide g after its rewrite: used when the reserving ?X
  // became a drawn segment, free again otherwise.
  void resolve(std::size_t g, std::size_t r, bool rewrote, const std::vector<std::size_t>& origins, int step) {
    const GuideRunner& runner = guides_[g];
    const SeedRun& run = runner.runs[r];
    for (auto it = reservations_.begin(); it != reservations_.end();) {
      if (it->guide != g || it->run != r) {
        ++it;
        continue;
      }
      bool reached = false;
      if (rewrote) {
        const auto [first, last] = std::equal_range(origins.begin(), origins.end(), it->module);
        for (auto k = first; k != last && !reached; ++k) {
          const std::size_t index = static_cast<std::size_t>(k - origins.begin());
          reached = run.fresh[index] && std::find(runner.turtle.draw_symbols.begin(), runner.turtle.draw_symbols.end(),
                                                  run.modules[index].symbol) != runner.turtle.draw_symbols.end();
        }
      }
      TokenState& token = tokens_[it->link];
      --token.reserved;
      if (reached) {
        ++token.used;
        schedule({step, scene_.links[it->link].to_guide, true, it->link, it->t, std::move(it->carried)});
      } else {
        ++token.free;
      }
      it = reservations_.erase(it);
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
