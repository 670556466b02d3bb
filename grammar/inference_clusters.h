#pragma once
// Cluster analysis in the transformation spaces (Št'ava et al. 2010 §5.3-§5.4): pairs of equal
// elements vote with their transform (alpha, d, s, beta); mean shift clusters them in the full
// space and in subspaces; clusters become sequence candidates (chains with a transform that is
// constant or changes linearly with the counter m) and branching candidates (complete binary
// trees of two constant transforms), each ranked by the importance w_n n + w_h h + w_phi phi + w_l l.

#include "grammar/inference_transform.h"

#include <cstddef>
#include <string>
#include <vector>

namespace dg {

/// An element of the scene during the hierarchy: an instance of a terminal or of a rule.
struct SceneNode {
  std::string type;            ///< equal types are interchangeable: "A", "P0(3)", ...
  InstanceFrame frame;
  InstanceFrame exit;          ///< where the turtle is after placing it (a segment moves it to its end)
  std::vector<Vec2> samples;   ///< points on its strokes (y-up), for proximity
  double similarity = 1;       ///< how well it matches its type's representative
};

/// Weights of the importance function (§5.4, equation 5), each in [0, 1]. n is the number of
/// elements a rule absorbs, h the proximity of linked elements (1 - closest sample distance /
/// drawing diagonal), phi their similarity, l the mean number of elements per rule instance;
/// n and l are divided by their largest value over all candidates.
struct ImportanceWeights {
  double w_n = 1.0;    ///< prefers rules that absorb many elements
  double w_h = 0.5;    ///< prefers merging neighbours first
  double w_phi = 0.5;  ///< prefers merging similar elements first
  double w_l = 0.5;    ///< prefers long sequences / deep trees
};

/// Bandwidths and tolerances of the cluster analysis.
struct ClusterOptions {
  ImportanceWeights weights;
  int neighbours = 12;                  ///< pairs are formed with this many nearest equal elements
  double angle_bandwidth_deg = 2.0;     ///< mean shift bandwidth of alpha and beta
  double log_distance_bandwidth = 0.03; ///< of log d
  double log_scale_bandwidth = 0.03;    ///< of log s
  double angle_tolerance_deg = 1.5;     ///< largest deviation of a link from the fitted rule
  double relative_tolerance = 0.03;     ///< same for d (relative) and s
  int max_branch_clusters = 8;          ///< largest clusters per type tried as branch pairs
};

/// A rule the scene could be rewritten with: a sequence `P(m) -> X T(m) P(m-1)`, a branching
/// `R(m) -> X [T1 R(m-1)] T2 R(m-1)`, or a pair of different types `Q -> X T Y`.
struct RuleCandidate {
  bool branching = false;
  bool pair = false;
  std::string child_type;             ///< type of every absorbed element (pairs: of the first)
  std::string second_type;            ///< pairs: type of the second element
  TurtleTransform start{};            ///< sequence: t0 of t(m) = t0 + slope m; branching: first branch
  TurtleTransform slope{};            ///< sequence only
  TurtleTransform second{};           ///< branching: the second branch (constant)
  std::vector<std::vector<std::size_t>> groups;  ///< node indices per new instance; groups[i][0] is its origin
  std::vector<int> counters;          ///< m of each new instance (chain length, or tree depth)
  std::size_t absorbed = 0;           ///< nodes removed by the rule (sum of group sizes - groups)
  double score = 0;
};

/// All candidates for the current scene (pairs of different types only when `pairs_of_types`), best first (ties broken by the transforms, so the
/// order does not depend on the order of the nodes). `diagonal` is the drawing's diagonal.
std::vector<RuleCandidate> find_rule_candidates(const std::vector<SceneNode>& nodes, double diagonal,
                                                const ClusterOptions& options);

}  // namespace dg
