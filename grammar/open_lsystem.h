#pragma once
// Open L-systems (Měch & Prusinkiewicz 1996; Beneš et al. 2011): query modules `?NAME(...)`
// whose parameters an environment fills in between derivation steps, and the `cut` symbol that
// ends a branch. The grammar core knows no geometry: what a query means is the environment's.

#include "grammar/derivation.h"
#include "grammar/lsystem.h"

#include <cstddef>
#include <string_view>
#include <vector>

namespace dg {

/// The symbol that erases itself and everything after it up to the end of its branch.
inline constexpr std::string_view cut_symbol = "cut";

/// True for query symbols: `?` followed by letters (`?X`, `?DL`, `?seed`).
bool is_query_symbol(std::string_view symbol);

/// Removes every `cut` together with the modules after it up to the `]` that closes its branch
/// (kept) or the end of the string. `origins` and `fresh`, when given, are filtered alike
/// (they run parallel to `modules`). Returns the number of modules removed.
std::size_t apply_cuts(std::vector<Module>& modules, std::vector<std::size_t>* origins = nullptr,
                       std::vector<char>* fresh = nullptr);

/// What answers query modules. `answer` is called after the axiom is set and after every step
/// (cuts already applied); it may change the parameters of query modules (and nothing else).
/// `fresh[i]` is 1 when modules[i] was just made by a production (or is in the axiom) and 0
/// when it is an unchanged copy, so a query is answered once, when it appears.
struct QueryEnvironment {
  virtual ~QueryEnvironment() = default;
  virtual void answer(std::vector<Module>& modules, const std::vector<char>& fresh) = 0;
};

/// Derives like derive() but lets `environment` answer the queries before every step and
/// applies cuts after every step. Stops when a step rewrites nothing; throws LimitError when
/// the step count (options.steps, else the system's iterations, else options.limits.max_steps)
/// runs out while the system is still rewriting and no step count was given.
Derivation derive_open(const LSystem& system, QueryEnvironment& environment, const DerivationOptions& options = {});

}  // namespace dg
