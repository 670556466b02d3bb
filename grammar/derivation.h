#pragma once
// Derivation: parallel rewriting of a module string by an L-system's productions.

#include "grammar/lsystem.h"
#include "geometry/random.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace dg {

/// Limits that stop runaway grammars with a LimitError instead of exhausting memory or time.
struct DerivationLimits {
  std::size_t max_modules = 5'000'000;  ///< largest string any step may produce
  int max_steps = 100'000;              ///< most steps of "rewrite until nothing applies"
};

/// How to derive. `steps` absent: use the L-system's `iterations`, and when that is absent too,
/// rewrite until no production applies to any module.
struct DerivationOptions {
  std::optional<int> steps;
  std::uint64_t seed = 1;  ///< seeds the choice among stochastic alternatives
  DerivationLimits limits;
};

/// The derived string and the number of steps that rewrote at least one module.
struct Derivation {
  std::vector<Module> modules;
  int steps = 0;
};

/// One parallel rewriting step at a time, for callers that interleave steps with other work
/// (Open L-systems answer their queries between steps). Keeps a pointer to `system`.
class Rewriter {
 public:
  explicit Rewriter(const LSystem& system);

  /// Rewrites every module of `modules` once (stochastic choices drawn from `random` in string
  /// order) and appends the result to `out`; modules copied unchanged are moved out of
  /// `modules` (it is left for the caller to discard). When given, `origins` gets for each appended
  /// module the index in `modules` it comes from, and `fresh` gets 1 for modules made by a
  /// production and 0 for copies. Returns whether any module was rewritten. Throws LimitError
  /// beyond `max_modules` (message names `step`) and InputError for non-finite arguments.
  bool step(std::vector<Module>& modules, Random& random, std::vector<Module>& out,
            std::vector<std::size_t>* origins, std::vector<char>* fresh, std::size_t max_modules, int step) const;

 private:
  std::unordered_map<std::string, std::vector<const Production*>> by_symbol_;
};

/// Rewrites the axiom step by step; each step rewrites every module in parallel (context-free).
/// Stochastic choices draw from one stream seeded by options.seed, in string order, so the same
/// system and seed always give the same string. Stops early when a step rewrites nothing.
/// Throws LimitError when a limit is exceeded and InputError when a successor argument is not
/// a finite number (e.g. a division by zero).
Derivation derive(const LSystem& system, const DerivationOptions& options = {});

}  // namespace dg
