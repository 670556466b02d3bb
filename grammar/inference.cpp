#include "grammar/inference.h"

#include "geometry/errors.h"
#include "grammar/expression.h"
#include "grammar/lsystem_text.h"

#include <algorithm>
#include <chrono>
#include <numbers>
#include <cmath>
#include <optional>
#include <set>
#include <sstream>

namespace dg {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double rounded(double value, int decimals) {
  const double f = std::pow(10.0, decimals);
  const double r = std::round(value * f) / f;
  return r == 0 ? 0 : r;  // no "-0"
}

std::string number(double value, int decimals) { return format_number(rounded(value, decimals)); }

constexpr int kAngleDecimals = 2, kDistanceDecimals = 3, kScaleDecimals = 4;

// Text of a linear expression start + slope * m.
std::string linear(double start, double slope, int decimals) {
  std::string text = number(start, decimals);
  const double s = std::abs(slope);
  const int slope_decimals = decimals + 2;
  text += slope < 0 ? '-' : '+';
  text += number(s, slope_decimals);
  text += "*m";
  return text;
}

// Turtle commands of +(alpha) f(d) *(s) +(beta), leaving out the trivial ones (§5.7).
std::string transform_text(const TurtleTransform& start, const TurtleTransform& slope) {
  std::vector<std::string> parts;
  auto turn = [&](int c) {
    if (slope[c] != 0) return parts.push_back("+(" + linear(start[c], slope[c], kAngleDecimals) + ")");
    const double v = rounded(start[c], kAngleDecimals);
    if (std::abs(v) >= trivial_turn_deg) parts.push_back(std::string(v > 0 ? "+(" : "-(") + format_number(std::abs(v)) + ")");
  };
  turn(0);
  if (slope[1] != 0) parts.push_back("f(" + linear(start[1], slope[1], kDistanceDecimals) + ")");
  else if (std::abs(start[1]) >= trivial_move) parts.push_back("f(" + number(start[1], kDistanceDecimals) + ")");
  if (slope[2] != 0) parts.push_back("*(" + linear(start[2], slope[2], kScaleDecimals) + ")");
  else if (std::abs(start[2] - 1) >= trivial_scale) parts.push_back("*(" + number(start[2], kScaleDecimals) + ")");
  turn(3);
  std::string text;
  for (const std::string& p : parts) text += (text.empty() ? "" : " ") + p;
  return text;
}

std::string join(std::initializer_list<std::string> parts) {
  std::string text;
  for (const std::string& p : parts)
    if (!p.empty()) text += (text.empty() ? "" : " ") + p;
  return text;
}

// `[text]`.
std::string bracketed(const std::string& text) {
  std::string out(1, '[');
  out += text;
  out += ']';
  return out;
}

// How a node of `type` is written inside a successor: terminals as they are, rule instances in
// brackets because they move the turtle.
std::string placed(const std::string& type, bool last, const std::set<std::string>& pair_types) {
  const bool terminal = type.find('(') == std::string::npos && !pair_types.count(type);
  return terminal || last ? type : bracketed(type);
}

std::string path_text(const ElementShape& shape) {
  std::string text;
  for (const auto& line : shape)
    for (std::size_t k = 0; k < line.size(); ++k)
    {
      if (!text.empty()) text += ' ';
      text += k == 0 ? "M " : "L ";
      text += number(line[k].x(), 3);
      text += ' ';
      text += number(line[k].y(), 3);
    }
  return text;
}

bool node_before(const SceneNode& a, const SceneNode& b) {
  const Vec2 &p = a.frame.position, &q = b.frame.position;
  if (p.x() != q.x()) return p.x() < q.x();
  if (p.y() != q.y()) return p.y() < q.y();
  if (a.frame.angle_deg != b.frame.angle_deg) return a.frame.angle_deg < b.frame.angle_deg;
  return a.type < b.type;
}

// A motif's frame may be turned freely (the motif turns back by the same angle). Each motif
// terminal is turned so that the first transform of its most important rule has alpha = 0: the
// turtle then moves straight ahead, which saves a turn in the rule.
void align_motif_frames(std::vector<SceneNode>& nodes, Instancing& instancing, double diagonal, const ClusterOptions& options) {
  const std::vector<RuleCandidate> candidates = find_rule_candidates(nodes, diagonal, options);
  for (Terminal& terminal : instancing.terminals) {
    if (terminal.segment) continue;
    const auto best = std::find_if(candidates.begin(), candidates.end(),
                                   [&](const RuleCandidate& c) { return c.child_type == terminal.symbol && c.absorbed > 0; });
    if (best == candidates.end() || best->slope[0] != 0 || std::abs(best->start[0]) < trivial_turn_deg) continue;
    const double offset = best->start[0];
    for (SceneNode& node : nodes)
      if (node.type == terminal.symbol) {
        node.frame.angle_deg = wrap_degrees(node.frame.angle_deg + offset);
        node.exit = node.frame;
      }
    const Eigen::Rotation2Dd back(-offset * std::numbers::pi / 180);
    for (auto& line : terminal.motif)
      for (Vec2& p : line) p = back * p;
  }
}

}  // namespace

InferredLSystem infer_lsystem(const SvgDrawing& drawing, const InferenceOptions& options) {
  const auto start_time = std::chrono::steady_clock::now();
  InferredLSystem result;
  std::vector<ElementShape> shapes;
  Vec2 low = Vec2::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (const SvgElement& element : drawing.elements) {
    ElementShape shape;
    for (const auto& line : element.polylines) {
      std::vector<Vec2> up;
      for (const Vec2& p : line) {
        up.emplace_back(p.x(), -p.y());
        low = low.cwiseMin(up.back());
        high = high.cwiseMax(up.back());
      }
      shape.push_back(std::move(up));
    }
    shapes.push_back(std::move(shape));
  }
  const Instancing instancing = inverse_instancing(shapes, options.similarity);
  if (instancing.instances.empty()) throw InputError("the drawing has no element with extent");
  result.elements = instancing.instances.size();
  result.terminals = instancing.terminals.size();
  result.timings.instancing_s = seconds_since(start_time);
  const double diagonal = (high - low).norm();

  const auto rules_start = std::chrono::steady_clock::now();
  std::vector<SceneNode> nodes;
  for (const TerminalInstance& instance : instancing.instances)
  {
    const Terminal& terminal = instancing.terminals[instance.terminal];
    // A segment `F` moves the turtle to its end; a motif leaves it in place.
    const InstanceFrame exit = terminal.segment ? apply_transform(instance.frame, {0, terminal.step, 1, 0}) : instance.frame;
    nodes.push_back(SceneNode{terminal.symbol, instance.frame, exit,
                              sample_points(shapes[instance.element], options.proximity_samples), instance.similarity});
  }

  Instancing terminals = instancing;
  align_motif_frames(nodes, terminals, diagonal, options.clusters);

  std::vector<std::string> rule_lines;
  std::optional<double> headline_angle, headline_scale;
  int sequences = 0, branchings = 0;
  std::set<std::string> pair_types;  // names of pair rules, which have no counter
  while (nodes.size() > 1 && static_cast<int>(result.rules) < options.max_rules) {
    const std::vector<RuleCandidate> candidates = find_rule_candidates(nodes, diagonal, options.clusters);
    const auto best = std::find_if(candidates.begin(), candidates.end(), [](const RuleCandidate& c) { return c.absorbed > 0; });
    if (best == candidates.end()) break;
    const RuleCandidate& rule = *best;
    std::string name = rule.pair ? "Q" : rule.branching ? "R" : "P";
    name.append(std::to_string(rule.pair ? static_cast<int>(pair_types.size()) : rule.branching ? branchings++ : sequences++));
    const std::string child = placed(rule.child_type, false, pair_types);
    if (rule.pair) {
      rule_lines.push_back(name + " -> " + join({child, transform_text(rule.start, {}), placed(rule.second_type, true, pair_types)}));
      pair_types.insert(name);
    } else if (rule.branching) {
      rule_lines.push_back(name + "(m) : m>0 -> " +
                           join({child, bracketed(join({transform_text(rule.start, {}), name + "(m-1)"})),
                                 transform_text(rule.second, {}), name + "(m-1)"}));
      rule_lines.push_back(name + "(m) : m==0 -> " + placed(rule.child_type, true, pair_types));
    } else {
      rule_lines.push_back(name + "(m) : m>0 -> " + join({child, transform_text(rule.start, rule.slope), name + "(m-1)"}));
      rule_lines.push_back(name + "(m) : m==0 -> ε");
    }
    if (!headline_angle) {
      for (int c : {0, 3})
        if (!headline_angle && rule.slope[c] == 0 && std::abs(rule.start[c]) >= trivial_turn_deg)
          headline_angle = std::abs(rounded(rule.start[c], kAngleDecimals));
    }
    if (!headline_scale && rule.slope[2] == 0 && std::abs(rule.start[2] - 1) >= trivial_scale)
      headline_scale = rounded(rule.start[2], kScaleDecimals);
    // Replace the absorbed nodes by one new node per group (§5.6), framed like its first node.
    std::vector<bool> absorbed(nodes.size(), false);
    std::vector<SceneNode> next;
    for (std::size_t g = 0; g < rule.groups.size(); ++g) {
      const auto& group = rule.groups[g];
      SceneNode node;
      node.type = rule.pair ? name : name + "(" + std::to_string(rule.counters[g]) + ")";
      node.frame = nodes[group.front()].frame;
      node.exit = node.frame;  // rule instances are placed in brackets
      double similarity = 0;
      std::size_t total = 0;
      for (std::size_t i : group) total += nodes[i].samples.size();
      const std::size_t stride = std::max<std::size_t>(1, total / static_cast<std::size_t>(std::max(1, options.group_samples)));
      std::size_t k = 0;
      for (std::size_t i : group) {
        absorbed[i] = true;
        similarity += nodes[i].similarity;
        for (const Vec2& p : nodes[i].samples)
          if (k++ % stride == 0) node.samples.push_back(p);
      }
      node.similarity = similarity / static_cast<double>(group.size());
      next.push_back(std::move(node));
    }
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (!absorbed[i]) next.push_back(std::move(nodes[i]));
    std::sort(next.begin(), next.end(), node_before);
    nodes = std::move(next);
    ++result.rules;
  }
  // The axiom: the first node at the turtle's start, the others placed from it (ω : T_X X).
  const SceneNode& root = nodes.front();
  std::string axiom;
  if (std::abs(root.frame.scale - 1) >= trivial_scale) axiom = "*(" + number(root.frame.scale, kScaleDecimals) + ")";
  axiom = join({axiom, placed(root.type, nodes.size() == 1, pair_types)});
  for (std::size_t i = 1; i < nodes.size(); ++i) {
    const TurtleTransform t = relative_transform(nodes.size() > 1 && root.type.find('(') == std::string::npos ? root.exit : root.frame,
                                                 nodes[i].frame);
    axiom = join({axiom, bracketed(join({transform_text(t, {}), nodes[i].type}))});
  }
  std::ostringstream text;
  text << "# inferred from a vector drawing: " << result.elements << " elements, " << result.terminals << " terminals, "
       << result.rules << " rules\n";
  text << "axiom: " << axiom << "\n";
  if (headline_angle) text << "angle: " << format_number(*headline_angle) << "\n";
  if (headline_scale) text << "scale: " << format_number(*headline_scale) << "\n";
  if (rounded(root.frame.angle_deg, kAngleDecimals) != 0) text << "heading: " << number(root.frame.angle_deg, kAngleDecimals) << "\n";
  for (const Terminal& terminal : terminals.terminals) {
    if (terminal.segment) text << "step: " << number(terminal.step, 4) << "\n";
    else text << "motif " << terminal.symbol << ": " << path_text(terminal.motif) << "\n";
  }
  for (const std::string& line : rule_lines) text << line << "\n";
  result.text = text.str();
  result.lsystem = parse_lsystem_text(result.text, "inferred L-system");
  result.start_svg = Vec2(root.frame.position.x(), -root.frame.position.y());
  result.timings.rules_s = seconds_since(rules_start);
  result.timings.total_s = seconds_since(start_time);
  return result;
}

}  // namespace dg
