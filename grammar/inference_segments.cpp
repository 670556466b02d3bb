#include "grammar/inference_segments.h"

#include "grammar/compaction.h"
#include "grammar/d0l_apex.h"
#include "grammar/d0l_chain.h"
#include "grammar/expression.h"
#include "grammar/inference_transform.h"
#include "grammar/lsystem_text.h"
#include "grammar/turtle_string.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>
#include <utility>

namespace dg {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string rounded_text(double value, int decimals) {
  const double f = std::pow(10.0, decimals);
  const double r = std::round(value * f) / f;
  return format_number(r == 0 ? 0 : r);
}

using Root = std::pair<std::size_t, bool>;  // segment, reversed

// A compacted grammar in text form: axiom, rules `predecessor -> successor`, drawing symbols.
struct FoundGrammar {
  std::string axiom;
  std::vector<std::pair<std::string, std::string>> rules;
  std::string draw;  // `draw:` setting, empty for F alone
  int iterations = 0;
  std::size_t length = 0;
  int angle_divisor = 1;  // the rules turn by the drawing's δ divided by this
  int start_turn = 0;     // the axiom's leading turn steps (of δ / angle_divisor), left to the start heading
};

// The shortest of the single-rule compaction, the one- or two-letter chain (unbranched strings;
// also with half the drawing's δ) and the apex system X -> u, F -> F^m (branched strings written
// with `descending_turns`).
FoundGrammar compact(const std::string& text, std::size_t max_block, bool descending_turns, std::optional<double> angle_deg) {
  const CompactGrammar single = compact_turtle_string(text, max_block);
  FoundGrammar found{single.axiom, {}, "", single.iterations, single.length, 1};
  if (single.iterations > 0) found.rules.emplace_back("F", single.successor);
  for (int turn_factor : {1, 2}) {
    // Steps of a full turn, when δ / turn_factor divides 360 (turns then wrap around).
    const double full = angle_deg ? 360 * turn_factor / *angle_deg : 0;
    const int full_turn = std::abs(full - std::round(full)) < 0.01 ? static_cast<int>(std::lround(full)) : 0;
    if (const auto chain = recover_chain_grammar(text, turn_factor, full_turn); chain && chain->length < found.length) {
      found = FoundGrammar{chain->axiom, {{"F", chain->f_successor}}, "", chain->iterations, chain->length, turn_factor,
                           chain->start_turn};
      if (!chain->g_successor.empty()) found.rules.emplace_back("G", chain->g_successor), found.draw = "F G";
    }
  }
  if (text.find('[') != std::string::npos && text.find('*') == std::string::npos)
    if (const auto apex = recover_apex_grammar(text, descending_turns); apex && apex->length < found.length)
      found = FoundGrammar{"X", {{"X", apex->apex_successor}, {"F", std::string(static_cast<std::size_t>(apex->m), 'F')}}, "",
                           apex->iterations, apex->length, 1};
  return found;
}

// Where a drawing may start: segments whose start no other segment reaches (directed), or
// segments with a free end (undirected); of those, the first in input order and the extreme
// ones in eight directions (lowest first). Without any free start (closed curves), the extreme
// segments of all.
std::vector<Root> candidate_roots(const std::vector<TreeSegment>& segments, bool directed, double tolerance, int limit) {
  auto key = [&](const Vec2& p) {
    return std::make_pair(static_cast<long long>(std::floor(p.x() / tolerance)), static_cast<long long>(std::floor(p.y() / tolerance)));
  };
  std::map<std::pair<long long, long long>, int> ends, all;
  for (const TreeSegment& s : segments) {
    ++ends[key(s.end)];
    ++all[key(s.start)];
    ++all[key(s.end)];
  }
  auto count_near = [&](const std::map<std::pair<long long, long long>, int>& grid, const Vec2& p) {
    const auto [cx, cy] = key(p);
    int n = 0;
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        const auto it = grid.find({cx + dx, cy + dy});
        if (it != grid.end()) n += it->second;
      }
    return n;
  };
  std::vector<Root> free;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (directed) {
      if (count_near(ends, segments[i].start) == 0) free.emplace_back(i, false);
    } else {
      if (count_near(all, segments[i].start) == 1) free.emplace_back(i, false);
      if (count_near(all, segments[i].end) == 1) free.emplace_back(i, true);
    }
  }
  std::vector<Root> pool = free;
  if (pool.empty())
    for (std::size_t i = 0; i < segments.size(); ++i) {
      pool.emplace_back(i, false);
      if (!directed) pool.emplace_back(i, true);
    }
  auto start_of = [&](const Root& r) { return r.second ? segments[r.first].end : segments[r.first].start; };
  std::vector<Root> roots;
  auto add = [&](const Root& r) {
    if (std::find(roots.begin(), roots.end(), r) == roots.end()) roots.push_back(r);
  };
  if (directed) add({0, false});
  const Vec2 directions[] = {{0, -1}, {0, 1}, {-1, 0}, {1, 0}, {-1, -1}, {1, 1}, {-1, 1}, {1, -1}};
  for (const Vec2& d : directions) {
    const auto best = std::max_element(pool.begin(), pool.end(), [&](const Root& a, const Root& b) {
      const double da = start_of(a).dot(d), db = start_of(b).dot(d);
      if (da != db) return da < db;
      return b < a;
    });
    add(*best);
    if (!directed) add({best->first, !best->second});
  }
  if (!free.empty() && free.size() <= static_cast<std::size_t>(limit))
    for (const Root& r : free) add(r);
  if (roots.size() > static_cast<std::size_t>(limit)) roots.resize(static_cast<std::size_t>(limit));
  return roots;
}

}  // namespace

std::optional<InferredLSystem> infer_segment_lsystem(const std::vector<TreeSegment>& segments, bool directed,
                                                     const SegmentInferenceOptions& options) {
  const auto start_time = std::chrono::steady_clock::now();
  if (segments.empty()) return std::nullopt;
  Vec2 low = segments.front().start, high = low;
  for (const TreeSegment& s : segments) {
    low = low.cwiseMin(s.start).cwiseMin(s.end);
    high = high.cwiseMax(s.start).cwiseMax(s.end);
  }
  const double diagonal = (high - low).norm();
  if (diagonal <= 0) return std::nullopt;
  InstanceTreeOptions tree_options;
  tree_options.directed = directed;
  tree_options.join_tolerance = options.join_fraction * diagonal;

  struct Best {
    FoundGrammar grammar;
    TurtleParameters parameters;
    TurtleString string;
    Vec2 start;
  };
  std::optional<Best> best;
  double tree_seconds = 0;
  auto try_tree = [&](const InstanceTree& tree) {
    if (tree.unreached > 0 || tree.nodes.empty()) return;
    const TurtleParameters parameters = estimate_turtle_parameters(tree);
    for (bool descending : {false, true}) {
      TurtleString string = tree_turtle_string(tree, parameters, descending, options.snap_angle_deg);
      if (descending && string.text.find('[') == std::string::npos) break;  // no branches: the same string again
      const double turn_limit = std::min(options.max_turn_error_deg, 0.4 * parameters.angle_deg.value_or(90));
      if (!string.expressible || string.worst_turn_error_deg > turn_limit ||
          string.worst_length_error > options.max_length_error)
        return;
      FoundGrammar grammar = compact(string.text, options.max_block, descending, string.angle_deg);
      // Shorter first; equal lengths: the start lowest, then leftmost (independent of input order).
      const Vec2 start = tree.nodes.front().start;
      const auto key = [](std::size_t length, const Vec2& p) {
        return std::make_tuple(length, std::round(p.y() * 1e3), std::round(p.x() * 1e3));
      };
      if (!best || key(grammar.length, start) < key(best->grammar.length, best->start))
        best = Best{std::move(grammar), parameters, std::move(string), tree.nodes.front().start};
    }
  };
  if (directed) {
    const auto tree_start = std::chrono::steady_clock::now();
    const InstanceTree tree = build_ordered_instance_tree(segments, tree_options.join_tolerance);
    tree_seconds += seconds_since(tree_start);
    try_tree(tree);
  }
  for (const Root& root : candidate_roots(segments, directed, tree_options.join_tolerance, options.max_roots)) {
    const auto tree_start = std::chrono::steady_clock::now();
    const InstanceTree tree = build_instance_tree(segments, root.first, root.second, tree_options);
    tree_seconds += seconds_since(tree_start);
    try_tree(tree);
  }
  if (!best) return std::nullopt;

  InferredLSystem result;
  result.method = "instance tree";
  result.elements = segments.size();
  result.terminals = 1;
  result.rules = best->grammar.iterations > 0 ? best->grammar.rules.size() : 0;
  std::ostringstream text;
  text << "# inferred from " << segments.size() << " segments: instance tree and repeated-block compaction (Guo et al. 2020)\n";
  const double unit = best->string.angle_deg.value_or(0) / best->grammar.angle_divisor;
  text << "axiom: " << best->grammar.axiom << "\n";
  if (best->string.angle_deg) text << "angle: " << rounded_text(unit, 2) << "\n";
  if (best->parameters.scale) text << "scale: " << rounded_text(*best->parameters.scale, 4) << "\n";
  text << "step: " << rounded_text(best->string.step, 4) << "\n";
  const double heading = wrap_degrees(best->string.heading_deg + best->grammar.start_turn * unit);
  if (rounded_text(heading, 2) != "0") text << "heading: " << rounded_text(heading, 2) << "\n";
  if (!best->grammar.draw.empty()) text << "draw: " << best->grammar.draw << "\n";
  if (best->grammar.iterations > 0) {
    text << "iterations: " << best->grammar.iterations << "\n";
    for (const auto& [predecessor, successor] : best->grammar.rules) text << predecessor << " -> " << successor << "\n";
  }
  result.text = text.str();
  result.lsystem = parse_lsystem_text(result.text, "inferred L-system");
  result.start_svg = Vec2(best->string.start.x(), -best->string.start.y());
  result.timings.instancing_s = tree_seconds;
  result.timings.total_s = seconds_since(start_time);
  result.timings.rules_s = result.timings.total_s - tree_seconds;
  return result;
}

}  // namespace dg
