#pragma once
// Productions (rewriting rules) `P(m) : m>0 -> A f(27.5) P(m-1)` of parametric, stochastic,
// context-free L-systems and of other grammars on the same core.

#include "grammar/expression.h"
#include "grammar/module.h"

#include <optional>
#include <string>
#include <vector>

namespace dg {

/// Rewrites a module whose symbol is `predecessor` and whose parameter count equals
/// formals.size(), when `condition` (evaluated with the formals bound) is nonzero or absent.
/// Among all productions that apply to one module, one is chosen at random with chance
/// proportional to `probability` (a weight; one applicable production is taken without a draw).
/// An empty successor erases the module (epsilon rule). A module that no production applies to
/// is copied unchanged.
struct Production {
  std::string predecessor;
  std::vector<std::string> formals;
  std::optional<Expression> condition;
  std::vector<SuccessorItem> successor;
  double probability = 1.0;

  friend bool operator==(const Production&, const Production&) = default;
};

}  // namespace dg
