#include "grammar/rule_pruning.h"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

namespace dg {
namespace {

// Keeps the non-terminals and productions flagged in `keep_nonterminal` and `keep_production`
// (a production of a dropped non-terminal goes too), renumbered densely in their order and the
// non-terminals named N1, N2, ... Kept productions must name kept non-terminals and kept
// productions only.
void keep_rules(ContextFreeGrammar& grammar, const std::vector<char>& keep_nonterminal, const std::vector<char>& keep_production) {
  std::vector<std::size_t> new_nonterminal(grammar.nonterminals.size(), kNoProduction);
  std::vector<ShapeNonterminal> nonterminals;
  for (std::size_t n = 0; n < grammar.nonterminals.size(); ++n) {
    if (!keep_nonterminal[n]) continue;
    new_nonterminal[n] = nonterminals.size();
    nonterminals.push_back(grammar.nonterminals[n]);
    nonterminals.back().name = fmt::format("N{}", nonterminals.size());
  }
  std::vector<std::size_t> new_production(grammar.productions.size(), kNoProduction);
  std::vector<ShapeProduction> productions;
  for (std::size_t p = 0; p < grammar.productions.size(); ++p) {
    if (!keep_production[p] || !keep_nonterminal[grammar.productions[p].lhs]) continue;
    new_production[p] = productions.size();
    productions.push_back(std::move(grammar.productions[p]));
  }
  auto renumber = [&](ShapeProduction& p) {
    if (p.lhs != kNoProduction) p.lhs = new_nonterminal[p.lhs];
    for (ChildSlot& slot : p.children) {
      slot.nonterminal = new_nonterminal[slot.nonterminal];
      slot.original_production = new_production[slot.original_production];
    }
  };
  for (ShapeProduction& p : productions) renumber(p);
  renumber(grammar.axiom);
  grammar.nonterminals = std::move(nonterminals);
  grammar.productions = std::move(productions);
}

}  // namespace

std::vector<char> reachable_nonterminals(const ContextFreeGrammar& grammar, std::vector<std::size_t> starts) {
  std::vector<char> reached(grammar.nonterminals.size(), 0);
  while (!starts.empty()) {
    const std::size_t n = starts.back();
    starts.pop_back();
    if (reached[n]) continue;
    reached[n] = 1;
    for (const ShapeProduction& p : grammar.productions)
      if (p.lhs == n)
        for (const ChildSlot& slot : p.children) starts.push_back(slot.nonterminal);
  }
  return reached;
}

std::size_t drop_unreachable_nonterminals(ContextFreeGrammar& grammar) {
  std::vector<std::size_t> starts;
  for (const ChildSlot& slot : grammar.axiom.children) starts.push_back(slot.nonterminal);
  const std::vector<char> reached = reachable_nonterminals(grammar, starts);
  keep_rules(grammar, reached, std::vector<char>(grammar.productions.size(), 1));
  return static_cast<std::size_t>(std::count(reached.begin(), reached.end(), 0));
}

std::size_t drop_alternatives_moving_the_model(ContextFreeGrammar& grammar, const std::vector<SwapMotion>& swaps) {
  std::vector<char> named(grammar.productions.size(), 0);
  auto mark = [&](const ShapeProduction& p) {
    for (const ChildSlot& slot : p.children) named[slot.original_production] = 1;
  };
  for (const ShapeProduction& p : grammar.productions) mark(p);
  mark(grammar.axiom);
  std::vector<std::size_t> production_count(grammar.nonterminals.size(), 0);
  for (const ShapeProduction& p : grammar.productions) ++production_count[p.lhs];
  auto children_vary = [&](const ShapeProduction& p) {
    std::vector<std::size_t> starts;
    for (const ChildSlot& slot : p.children) starts.push_back(slot.nonterminal);
    const std::vector<char> reached = reachable_nonterminals(grammar, starts);
    for (std::size_t n = 0; n < reached.size(); ++n)
      if (reached[n] && production_count[n] > 1) return true;
    return false;
  };
  std::vector<char> keep(grammar.productions.size(), 1);
  for (std::size_t p = 0; p < grammar.productions.size(); ++p) {
    const ShapeProduction& production = grammar.productions[p];
    const SwapMotion swap = swaps[production.lhs];
    if (swap == SwapMotion::none || named[p]) continue;
    if (swap == SwapMotion::elsewhere || !children_vary(production)) keep[p] = 0;
  }
  keep_rules(grammar, std::vector<char>(grammar.nonterminals.size(), 1), keep);
  return static_cast<std::size_t>(std::count(keep.begin(), keep.end(), 0));
}

}  // namespace dg
