// pipe_tree(depth): square pipes branching at T joints, like an H-tree standing up.
//
// A node of level l (l = 0 .. depth) is a vertical stem of height h. For l < depth the stem
// ends in a T joint: a horizontal bar along x (l even) or y (l odd), centred on the stem, with
// half-span s_l = span * 0.5^floor(l/2); the two child nodes of level l+1 stand on the bar ends.
// Level-depth nodes are leaves and end in a wider cap; the root stands on a wider flange. All
// nodes of one level, with their subtrees, are exact translated copies, so the rule
// "branch_l -> stem + bar + branch_{l+1} + branch_{l+1}" recurses; the bar length halves
// every second level (so branches never collide), the pipe section and stem height never change.
//
// Repetition "level_l" (l = 1 .. depth): the translation 2 s_{l-1} along the bar axis of level
// l-1 maps the first child subtree of every level-(l-1) node onto the second; count = 2 (the
// two subtrees), unit = one child subtree above the middle of its stem.

#include "assets/generator/box_solid.h"
#include "assets/generator/ground_truth.h"
#include "assets/generator/models.h"
#include "geometry/errors.h"

#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace dg::assets {

namespace {

constexpr double kFlange = 0.24;        // root flange width, m
constexpr double kFlangeHeight = 0.06;
constexpr double kCap = 0.16;           // leaf cap width
constexpr double kCapHeight = 0.05;

struct TreeShape {
  int depth = 0;
  double pipe = 0.0;   // square section side
  double stem = 0.0;   // stem height
  double span = 0.0;   // half-span of the level-0 bar
};

/// Half-span of the bar of level l.
double half_span(const TreeShape& shape, int level) { return shape.span * std::ldexp(1.0, -(level / 2)); }

/// Axis (0 = x, 1 = y) of the bar of level l.
int bar_axis(int level) { return level % 2; }

/// Height of the bottom of a level-l stem.
double stem_base(const TreeShape& shape, int level) { return level * (shape.stem + shape.pipe); }

/// Adds the node of `level` whose stem axis passes through (x, y), with its subtree.
void add_node(BoxSolid& solid, const TreeShape& shape, int level, double x, double y) {
  const double w = shape.pipe / 2, base = stem_base(shape, level), top = base + shape.stem;
  add_box(solid, Vec3(x - w, y - w, base), Vec3(x + w, y + w, top));
  add_seam(solid, 2, base + shape.stem / 2);
  if (level == shape.depth) {
    add_box(solid, Vec3(x - kCap / 2, y - kCap / 2, top), Vec3(x + kCap / 2, y + kCap / 2, top + kCapHeight));
    return;
  }
  const double s = half_span(shape, level);
  const Vec3 along = bar_axis(level) == 0 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
  const Vec3 across = Vec3(1.0, 1.0, 0.0) - along;
  const Vec3 centre(x, y, top);
  add_box(solid, centre - (s + w) * along - w * across, centre + (s + w) * along + w * across + Vec3(0.0, 0.0, shape.pipe));
  for (double side : {-1.0, 1.0}) {
    const Vec3 child = centre + side * s * along;
    add_node(solid, shape, level + 1, child.x(), child.y());
  }
}

}  // namespace

Asset make_pipe_tree(const nlohmann::json& params) {
  Parameters p = read_parameters("pipe_tree", params);
  TreeShape shape;
  shape.depth = integer_parameter(p, "depth", 3, 0, 12);
  shape.pipe = number_parameter(p, "pipe_width", 0.1, 0.01, 0.2);
  shape.stem = number_parameter(p, "stem_height", 1.0, 0.3, 100.0);
  shape.span = number_parameter(p, "span", 1.6, 0.2, 100.0);
  const int detail = integer_parameter(p, "detail", 1, 1, 1000);
  reject_unknown_parameters(p);
  if (shape.depth >= 2 && half_span(shape, shape.depth - 1) < 2 * kCap) {
    throw InputError(fmt::format("pipe_tree: span {} is too small for depth {} (branches would touch)", shape.span, shape.depth));
  }

  BoxSolid solid;
  add_box(solid, Vec3(-kFlange / 2, -kFlange / 2, 0.0), Vec3(kFlange / 2, kFlange / 2, kFlangeHeight));
  add_node(solid, shape, 0, 0.0, 0.0);
  TriangleMesh mesh = box_solid_surface(solid, detail);

  // Unit of level l: the first child subtree of the first level-(l-1) node (all sides negative),
  // cut at the middle of its stem; a box of half-width s_{l-1} along the bar axis of level l-1
  // around its axis holds it alone.
  std::vector<Repetition> repetitions;
  const double inf = std::numeric_limits<double>::infinity();
  Vec3 node(0.0, 0.0, 0.0);
  for (int level = 1; level <= shape.depth; ++level) {
    const double s = half_span(shape, level - 1);
    const Vec3 along = bar_axis(level - 1) == 0 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
    node -= s * along;
    Repetition r = translation_repetition(
        fmt::format("level_{}", level), 2 * s * along, 2,
        fmt::format("one level-{} subtree (stem from its middle up, with everything it carries); the translation maps "
                    "the first child of every level-{} node onto the second; count = 2 children per T joint",
                    level, level - 1));
    // Along the other axis the nearest foreign subtrees (cousins) are 2 s_{l-2} away.
    const double other = level >= 2 ? half_span(shape, level - 2) : inf;
    const Vec3 half = bar_axis(level - 1) == 0 ? Vec3(s, other, 0.0) : Vec3(other, s, 0.0);
    const double z = stem_base(shape, level) + shape.stem / 2;
    r.measure = measure_unit(mesh, box_region(Vec3(node.x() - half.x(), node.y() - half.y(), z),
                                              Vec3(node.x() + half.x(), node.y() + half.y(), inf)));
    repetitions.push_back(std::move(r));
  }

  nlohmann::json levels = nlohmann::json::array();
  for (int level = 0; level <= shape.depth; ++level) {
    levels.push_back({{"level", level},
                      {"nodes", 1 << level},
                      {"stem_base", stem_base(shape, level)},
                      {"bar_axis", level == shape.depth ? "none" : (bar_axis(level) == 0 ? "x" : "y")},
                      {"bar_half_span", level == shape.depth ? 0.0 : half_span(shape, level)}});
  }
  const nlohmann::json notes = {
      {"description", "square pipes branching at T joints (H-tree standing on a flange, leaves capped)"},
      {"levels", levels},
      {"recursion_depth", shape.depth}};
  return finish_asset(fmt::format("pipe_tree_{}", shape.depth), p, std::move(mesh), repetitions, nullptr, notes);
}

}  // namespace dg::assets
