#pragma once
// Grammar generalization by greedy rule merging (Guo et al. 2020 §4.3, Algorithm 2): two rules
// with different predecessors A and B are merged by writing B as A everywhere; A then has both
// right-hand sides as stochastic alternatives of equal probability. A merge is taken while its
// cost w_0 (L(L*) - L(L+)) + (1 - w_0) D_g is negative, cheapest first, where L is the grammar
// length and D_g the weighted edit distance between the merged right-hand sides. Works on any
// grammar of the core (grammar/lsystem.h), not on 2D types.

#include "grammar/lsystem.h"

#include <string>
#include <vector>

namespace dg {

/// Weights of the merging cost and of the edit operations (Guo: 1.0, 1.5, 1.5).
struct GeneralizationOptions {
  double w0 = 0.5;             ///< weight of the length change against the edit distance, in [0, 1]
  double replace_cost = 1.0;
  double insert_cost = 1.5;
  double delete_cost = 1.5;
};

/// Weighted edit distance (dynamic programming) between two successors; items are equal when
/// their symbols and argument expressions are equal.
double weighted_edit_distance(const std::vector<SuccessorItem>& a, const std::vector<SuccessorItem>& b,
                              const GeneralizationOptions& options = {});

/// One merge: `merged` was renamed to `kept`; `cost` is its change of the objective.
struct RuleMerge {
  std::string kept;
  std::string merged;
  double edit_distance = 0;
  double cost = 0;
};

/// The generalized grammar and the merges in the order they were made.
struct Generalization {
  LSystem system;
  std::vector<RuleMerge> merges;
};

/// Merges rules greedily as described above. Only predecessors with productions and the same
/// parameter count are merged; identical productions that result are kept once (their weights
/// added). The axiom and turtle settings are rewritten with the new names.
Generalization generalize(const LSystem& system, const GeneralizationOptions& options = {});

}  // namespace dg
