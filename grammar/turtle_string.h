#pragma once
// From an instance tree to the bracketed turtle string that draws it (symbols F + - [ ] *),
// with the turtle parameters estimated from the tree (Guo et al. 2020 §4.2, rule parameter
// estimation): the turn of `+`/`-` (δ) by clustering the turns between linked segments, the
// factor of `*` by clustering their length ratios, the step by averaging the segment lengths
// divided by their scale.

#include "grammar/instance_tree.h"

#include <cstddef>
#include <optional>
#include <string>

namespace dg {

/// Turtle parameters of a tree of segments.
struct TurtleParameters {
  std::optional<double> angle_deg;  ///< δ in degrees (absent when no link turns)
  std::optional<double> scale;      ///< factor of `*`, below 1 (absent when all links keep the length)
};

/// δ: the turns between linked segments are clustered (sorted, split at gaps over 3 degrees);
/// the smallest cluster of at least 5 degrees holding 2 % of the links gives δ, refined by least
/// squares over all turns as multiples of it (turns under 5 degrees count as straight). Scale:
/// likewise on |log| of the length ratios child / parent (gaps 0.03, least log 1.08), below 1.
TurtleParameters estimate_turtle_parameters(const InstanceTree& tree);

/// The turtle string of a tree and how well it fits.
struct TurtleString {
  std::string text;               ///< one character per symbol: F + - [ ] *
  std::optional<double> angle_deg;  ///< δ refined on the absolute headings (see tree_turtle_string)
  double step = 0;                ///< length of F at scale 1, drawing units
  double heading_deg = 0;         ///< start heading, degrees counter-clockwise
  Vec2 start = Vec2::Zero();      ///< where the turtle starts, drawing units
                                  ///< (step, heading, start: the least-squares similarity that maps the
                                  ///< turtle's walk onto all segment end points, so errors do not add up)
  double worst_turn_error_deg = 0;  ///< largest |turn - k δ| over the links
  double worst_length_error = 0;    ///< largest relative |length - step s^j| over the nodes
  bool expressible = true;          ///< false when a link grows the length (needs a `/`)
};

/// Every node's heading should be the root's plus K δ, K its summed turn steps; δ is refined by
/// a search within ±5 degrees of the estimate (0.01 degree steps) for the least squared heading
/// residuals, which does not add up pixel errors along long chains as turns do; a refined δ within
/// `snap_angle_deg` of 360/k (k = 3..36) becomes 360/k.
/// Writes the tree depth first: a node is its turn (`+` or `-` repeated k times for k δ), its
/// scale change (`*` repeated j times for s^j), then `F`; its children follow, each in brackets
/// except the one with the largest subtree, which continues the branch unbracketed and comes
/// last. Bracketed children come smallest subtree first, ties by turn (ascending, or descending
/// with `descending_turns`), then by input order.
TurtleString tree_turtle_string(const InstanceTree& tree, const TurtleParameters& parameters, bool descending_turns,
                                double snap_angle_deg = 0);

/// The string a drawing of `text` gives (symbols F + - * [ ], anything else: nothing): its
/// segments as a tree (each F hangs below the last F of its branch; turns and scale steps add up
/// between them, so `+-` vanishes and brackets without F leave no trace) written as
/// tree_turtle_string writes trees. Nothing for unbalanced brackets or a drawing of two roots.
std::optional<std::string> canonical_turtle_string(const std::string& text, bool descending_turns);

}  // namespace dg
