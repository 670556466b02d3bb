#include "grammar/derivation.h"

#include "geometry/random.h"
#include "grammar/rule_syntax.h"

#include <cmath>
#include <string>

namespace dg {

namespace {

bool applies(const Production& production, const Module& module) {
  if (production.formals.size() != module.parameters.size()) return false;
  return !production.condition || evaluate(*production.condition, production.formals, module.parameters) != 0;
}

// The production that rewrites `module`, or nullptr; draws from `random` only when several apply.
const Production* choose(const std::vector<const Production*>& candidates, const Module& module, Random& random,
                         std::vector<const Production*>& scratch) {
  scratch.clear();
  double total = 0;
  for (const Production* production : candidates)
    if (applies(*production, module)) {
      scratch.push_back(production);
      total += production->probability;
    }
  if (scratch.size() <= 1) return scratch.empty() ? nullptr : scratch.front();
  double pick = random.uniform() * total;
  for (const Production* production : scratch) {
    pick -= production->probability;
    if (pick < 0) return production;
  }
  return scratch.back();
}

void append_successor(const Production& production, const Module& module, std::vector<Module>& out) {
  for (const SuccessorItem& item : production.successor) {
    Module child{item.symbol, {}};
    child.parameters.reserve(item.arguments.size());
    for (const Expression& argument : item.arguments) {
      const double value = evaluate(argument, production.formals, module.parameters);
      if (!std::isfinite(value))
        throw InputError("production " + format_left_side(production) + " gives " + item.symbol + " the argument " +
                         format_number(value) + " for " + format_module(module) + " (not a finite number)");
      child.parameters.push_back(value);
    }
    out.push_back(std::move(child));
  }
}

[[noreturn]] void too_many_modules(std::size_t limit, int step) {
  throw LimitError("derivation exceeds " + std::to_string(limit) + " modules at step " + std::to_string(step) +
                   "; raise --max-modules or use fewer iterations");
}

}  // namespace

Rewriter::Rewriter(const LSystem& system) {
  for (const Production& production : system.productions) by_symbol_[production.predecessor].push_back(&production);
}

bool Rewriter::step(std::vector<Module>& modules, Random& random, std::vector<Module>& out,
                    std::vector<std::size_t>* origins, std::vector<char>* fresh, std::size_t max_modules,
                    int step) const {
  std::vector<const Production*> scratch;
  bool rewrote = false;
  for (std::size_t i = 0; i < modules.size(); ++i) {
    Module& module = modules[i];
    const std::size_t before = out.size();
    const auto candidates = by_symbol_.find(module.symbol);
    const Production* production =
        candidates == by_symbol_.end() ? nullptr : choose(candidates->second, module, random, scratch);
    if (production) {
      append_successor(*production, module, out);
      rewrote = true;
    } else {
      out.push_back(std::move(module));
    }
    if (origins) origins->insert(origins->end(), out.size() - before, i);
    if (fresh) fresh->insert(fresh->end(), out.size() - before, production ? 1 : 0);
    if (out.size() > max_modules) too_many_modules(max_modules, step);
  }
  return rewrote;
}

Derivation derive(const LSystem& system, const DerivationOptions& options) {
  const std::optional<int> steps = options.steps ? options.steps : system.iterations;
  const Rewriter rewriter(system);
  Random random(options.seed);
  Derivation result;
  result.modules = system.axiom;
  if (result.modules.size() > options.limits.max_modules) too_many_modules(options.limits.max_modules, 0);
  std::vector<Module> next;
  for (int step = 1; !steps || step <= *steps; ++step) {
    if (!steps && step > options.limits.max_steps)
      throw LimitError("derivation still rewrites after " + std::to_string(options.limits.max_steps) +
                       " steps; give a number of iterations (-n) or check the rules for endless recursion");
    next.clear();
    const bool rewrote = rewriter.step(result.modules, random, next, nullptr, nullptr, options.limits.max_modules, step);
    result.modules.swap(next);  // also when nothing was rewritten: the modules were moved to `next`
    if (!rewrote) break;
    result.steps = step;
  }
  return result;
}

}  // namespace dg
