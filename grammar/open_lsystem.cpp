#include "grammar/open_lsystem.h"

#include <string>

namespace dg {

bool is_query_symbol(std::string_view symbol) { return symbol.size() > 1 && symbol.front() == '?'; }

std::size_t apply_cuts(std::vector<Module>& modules, std::vector<std::size_t>* origins, std::vector<char>* fresh) {
  std::size_t kept = 0;
  int skip_depth = -1;  // >= 0: inside a cut branch, counting brackets opened since the cut
  for (std::size_t i = 0; i < modules.size(); ++i) {
    const std::string& symbol = modules[i].symbol;
    if (skip_depth >= 0) {
      if (symbol == "[") ++skip_depth;
      if (symbol == "]" && skip_depth-- == 0) skip_depth = -1;  // the closing bracket of the cut branch stays
      if (skip_depth >= 0) continue;
    } else if (symbol == cut_symbol) {
      skip_depth = 0;
      continue;
    }
    if (kept != i) {
      modules[kept] = std::move(modules[i]);
      if (origins) (*origins)[kept] = (*origins)[i];
      if (fresh) (*fresh)[kept] = (*fresh)[i];
    }
    ++kept;
  }
  const std::size_t removed = modules.size() - kept;
  modules.resize(kept);
  if (origins) origins->resize(kept);
  if (fresh) fresh->resize(kept);
  return removed;
}

Derivation derive_open(const LSystem& system, QueryEnvironment& environment, const DerivationOptions& options) {
  const std::optional<int> steps = options.steps ? options.steps : system.iterations;
  const Rewriter rewriter(system);
  Random random(options.seed);
  Derivation result;
  result.modules = system.axiom;
  std::vector<char> fresh(result.modules.size(), 1);
  apply_cuts(result.modules, nullptr, &fresh);
  std::vector<Module> next;
  std::vector<char> next_fresh;
  for (int step = 1; !steps || step <= *steps; ++step) {
    environment.answer(result.modules, fresh);
    if (!steps && step > options.limits.max_steps)
      throw LimitError("open L-system still rewrites after " + std::to_string(options.limits.max_steps) +
                       " steps (derivation limit); check the rules for endless growth");
    next.clear();
    next_fresh.clear();
    const bool rewrote = rewriter.step(result.modules, random, next, nullptr, &next_fresh, options.limits.max_modules, step);
    result.modules.swap(next);  // also when nothing was rewritten: the modules were moved to `next`
    if (!rewrote) break;
    apply_cuts(result.modules, nullptr, &next_fresh);
    fresh.swap(next_fresh);
    result.steps = step;
  }
  return result;
}

}  // namespace dg
