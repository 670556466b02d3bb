#include "grammar/turtle_string.h"

#include "grammar/inference_transform.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <limits>
#include <numeric>

namespace dg {

namespace {

double heading_of(const TreeSegment& s) {
  const Vec2 d = s.end - s.start;
  return std::atan2(d.y(), d.x()) * 180 / std::numbers::pi;
}

double length_of(const TreeSegment& s) { return (s.end - s.start).norm(); }

// The unit of which the values are integer multiples: the sorted values are split into
// clusters where neighbours differ by more than `gap`; the first cluster whose centre is at
// least `least` and that holds at least 2 % of the values gives a first unit (its median), which
// is refined by least squares over all values of at least `least` as multiples of it. Nothing
// when no cluster qualifies.
std::optional<double> base_unit(const std::vector<double>& sorted, double gap, double least) {
  std::optional<double> unit;
  for (std::size_t begin = 0; begin < sorted.size() && !unit;) {
    std::size_t end = begin + 1;
    while (end < sorted.size() && sorted[end] - sorted[end - 1] <= gap) ++end;
    const double median = sorted[(begin + end) / 2];
    if (median >= least && (end - begin) * 50 >= sorted.size()) unit = median;
    begin = end;
  }
  if (!unit) return std::nullopt;
  double numerator = 0, denominator = 0;
  for (double v : sorted) {
    if (v < least) continue;
    const double k = std::max(1.0, std::round(v / *unit));
    numerator += v * k;
    denominator += k * k;
  }
  return numerator / denominator;
}

// Depth first from node 0 (parents are numbered before their children), with an explicit stack
// (chains may be thousands of segments deep); the order of children as tree_turtle_string tells.
std::string write_turtle_tree(const std::vector<std::vector<std::size_t>>& children, const std::vector<int>& turn_steps,
                              const std::vector<int>& scale_steps, bool descending_turns) {
  const std::size_t n = children.size();
  std::string text;
  if (n == 0) return text;
  std::vector<std::size_t> size(n, 1);
  for (std::size_t v = n; v-- > 0;)
    for (std::size_t c : children[v]) size[v] += size[c];
  struct Item {
    std::size_t node;
    bool bracketed;
    bool close;
  };
  std::vector<Item> stack{{0, false, false}};
  std::vector<std::size_t> order;
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    if (item.close) {
      text += ']';
      continue;
    }
    const std::size_t v = item.node;
    if (item.bracketed) text += '[';
    text.append(static_cast<std::size_t>(std::abs(turn_steps[v])), turn_steps[v] > 0 ? '+' : '-');
    text.append(static_cast<std::size_t>(scale_steps[v]), '*');
    text += 'F';
    order = children[v];
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      if (size[a] != size[b]) return size[a] < size[b];
      return descending_turns ? turn_steps[a] > turn_steps[b] : turn_steps[a] < turn_steps[b];
    });
    for (std::size_t k = order.size(); k-- > 0;) {
      if (k + 1 == order.size()) {
        stack.push_back({order[k], false, false});
      } else {
        stack.push_back({0, false, true});
        stack.push_back({order[k], true, false});
      }
    }
  }
  return text;
}

}  // namespace

TurtleParameters estimate_turtle_parameters(const InstanceTree& tree) {
  std::vector<double> turns, shrinks;
  for (std::size_t p = 0; p < tree.nodes.size(); ++p)
    for (std::size_t c : tree.children[p]) {
      const double turn = std::abs(wrap_degrees(heading_of(tree.nodes[c]) - heading_of(tree.nodes[p])));
      turns.push_back(turn);
      const double lp = length_of(tree.nodes[p]), lc = length_of(tree.nodes[c]);
      if (lp <= 0 || lc <= 0) continue;
      shrinks.push_back(std::abs(std::log(lc / lp)));
    }
  TurtleParameters parameters;
  std::sort(turns.begin(), turns.end());
  std::sort(shrinks.begin(), shrinks.end());
  parameters.angle_deg = base_unit(turns, 3.0, 5.0);
  if (const auto shrink = base_unit(shrinks, 0.03, std::log(1.08))) parameters.scale = std::exp(-*shrink);
  return parameters;
}

TurtleString tree_turtle_string(const InstanceTree& tree, const TurtleParameters& parameters, bool descending_turns,
                                double snap_angle_deg) {
  TurtleString result;
  const std::size_t n = tree.nodes.size();
  if (n == 0) return result;
  // Turn steps and scale steps of every node relative to its parent.
  std::vector<int> turn_steps(n, 0), scale_steps(n, 0), exponent(n, 0);
  const double delta = parameters.angle_deg.value_or(0);
  const double log_scale = parameters.scale ? std::log(*parameters.scale) : 0;
  for (std::size_t p = 0; p < n; ++p)
    for (std::size_t c : tree.children[p]) {
      const double turn = wrap_degrees(heading_of(tree.nodes[c]) - heading_of(tree.nodes[p]));
      const int k = delta > 0 ? static_cast<int>(std::lround(turn / delta)) : 0;
      turn_steps[c] = k;
      result.worst_turn_error_deg = std::max(result.worst_turn_error_deg, std::abs(turn - k * delta));
      const double lp = length_of(tree.nodes[p]), lc = length_of(tree.nodes[c]);
      int j = 0;
      if (log_scale != 0 && lp > 0 && lc > 0) j = static_cast<int>(std::lround(std::log(lc / lp) / log_scale));
      if (j < 0) result.expressible = false;
      scale_steps[c] = std::max(0, j);
      exponent[c] = exponent[p] + scale_steps[c];
    }
  std::vector<int> summed(n, 0);
  for (std::size_t p = 0; p < n; ++p)
    for (std::size_t c : tree.children[p]) summed[c] = summed[p] + turn_steps[c];
  if (delta > 0) {
    const double root_heading = heading_of(tree.nodes.front());
    std::vector<double> relative(n);  // headings relative to the root's, computed once
    for (std::size_t v = 0; v < n; ++v) relative[v] = heading_of(tree.nodes[v]) - root_heading;
    double best_cost = std::numeric_limits<double>::infinity();
    for (int k = -500; k <= 500; ++k) {
      const double candidate = delta + 0.01 * k;
      double cost = 0;
      for (std::size_t v = 0; v < n; ++v) {
        const double d = relative[v] - summed[v] * candidate;
        const double r = d - 360 * std::nearbyint(d / 360);  // wrapped into [-180, 180]
        cost += r * r;
      }
      if (cost < best_cost) best_cost = cost, result.angle_deg = candidate;
    }
    for (int k = 3; k <= 36; ++k)
      if (std::abs(*result.angle_deg - 360.0 / k) <= snap_angle_deg) {
        result.angle_deg = 360.0 / k;
        break;
      }
  }
  // Step and heading: the least-squares similarity (complex factor z = step e^{i heading}) that
  // maps the turtle's walk with unit step and heading 0 onto the node end points.
  const double unit_delta = (result.angle_deg ? *result.angle_deg : delta) * std::numbers::pi / 180;
  std::vector<std::complex<double>> walk(n);
  for (std::size_t v = 0; v < n; ++v) walk[v] = std::polar(std::exp(exponent[v] * log_scale), summed[v] * unit_delta);
  for (std::size_t p = 0; p < n; ++p)
    for (std::size_t c : tree.children[p]) walk[c] += walk[p];  // parents come before children
  // Ends relative to the root's start, both sets centred (the root's start is measured too).
  const Vec2 origin = tree.nodes.front().start;
  std::complex<double> mean_walk = 0, mean_end = 0;
  std::vector<std::complex<double>> ends(n);
  for (std::size_t v = 0; v < n; ++v) {
    const Vec2 end = tree.nodes[v].end - origin;
    ends[v] = {end.x(), end.y()};
    mean_walk += walk[v];
    mean_end += ends[v];
  }
  mean_walk /= static_cast<double>(n);
  mean_end /= static_cast<double>(n);
  std::complex<double> numerator = 0;
  double denominator = 0;
  for (std::size_t v = 0; v < n; ++v) {
    numerator += std::conj(walk[v] - mean_walk) * (ends[v] - mean_end);
    denominator += std::norm(walk[v] - mean_walk);
  }
  const std::complex<double> z = denominator > 0 ? numerator / denominator : std::complex<double>(0);
  const std::complex<double> shift = mean_end - z * mean_walk;
  result.start = origin + Vec2(shift.real(), shift.imag());
  result.step = std::abs(z);
  result.heading_deg = std::arg(z) * 180 / std::numbers::pi;
  for (std::size_t v = 0; v < n; ++v) {
    const double expected = result.step * std::exp(exponent[v] * log_scale);
    if (expected > 0) result.worst_length_error = std::max(result.worst_length_error, std::abs(length_of(tree.nodes[v]) - expected) / expected);
  }

  result.text = write_turtle_tree(tree.children, turn_steps, scale_steps, descending_turns);
  return result;
}

std::optional<std::string> canonical_turtle_string(const std::string& text, bool descending_turns) {
  struct State {
    int heading = 0, scale = 0;
    std::optional<std::size_t> node;  // the last F drawn in this branch
  };
  std::vector<std::vector<std::size_t>> children;
  std::vector<int> heading, scale, turn_steps, scale_steps;
  std::vector<State> saved;
  State state;
  for (char c : text) {
    if (c == '+') ++state.heading;
    else if (c == '-') --state.heading;
    else if (c == '*') ++state.scale;
    else if (c == '[') saved.push_back(state);
    else if (c == ']') {
      if (saved.empty()) return std::nullopt;
      state = saved.back();
      saved.pop_back();
    } else if (c == 'F') {
      const std::size_t v = children.size();
      if (!state.node && v > 0) return std::nullopt;  // a second root
      children.emplace_back();
      heading.push_back(state.heading);
      scale.push_back(state.scale);
      turn_steps.push_back(state.node ? state.heading - heading[*state.node] : state.heading);
      scale_steps.push_back(state.node ? state.scale - scale[*state.node] : state.scale);
      if (state.node) children[*state.node].push_back(v);
      state.node = v;
    } else {
      return std::nullopt;
    }
  }
  if (!saved.empty()) return std::nullopt;
  return write_turtle_tree(children, turn_steps, scale_steps, descending_turns);
}

}  // namespace dg
