// Pruning a context-free grammar: unreachable non-terminals, and alternatives that only move
// the whole model, on small hand-made grammars.

#include "grammar/rule_pruning.h"

#include <catch2/catch.hpp>

#include <vector>

namespace {

using dg::ChildSlot;
using dg::ContextFreeGrammar;
using dg::ShapeProduction;

ChildSlot slot(std::size_t nonterminal, std::size_t original_production) {
  ChildSlot child;
  child.nonterminal = nonterminal;
  child.original_production = original_production;
  return child;
}

ShapeProduction production(std::size_t lhs, std::vector<ChildSlot> children, std::size_t source_site) {
  ShapeProduction p;
  p.lhs = lhs;
  p.children = std::move(children);
  p.source_site = source_site;  // tells the productions apart after renumbering
  return p;
}

// N1 and N2 have two productions each: N1's first (p0) is the exemplar's and names N2 through
// its exemplar production p2; N1's second (p1) is an alternative holding N2 as well; N2's p3 is
// an alternative leaf. N3 (p4) is reached by nothing. The axiom holds N1 via p0.
ContextFreeGrammar two_level_grammar() {
  ContextFreeGrammar grammar;
  for (const char* name : {"N1", "N2", "N3"}) {
    grammar.nonterminals.emplace_back();
    grammar.nonterminals.back().name = name;
  }
  grammar.productions = {production(0, {slot(1, 2)}, 10), production(0, {slot(1, 2)}, 11), production(1, {}, 12),
                         production(1, {}, 13), production(2, {}, 14)};
  grammar.axiom = production(dg::kNoProduction, {slot(0, 0)}, 0);
  return grammar;
}

std::vector<std::size_t> sites(const ContextFreeGrammar& grammar) {
  std::vector<std::size_t> result;
  for (const ShapeProduction& p : grammar.productions) result.push_back(p.source_site);
  return result;
}

}  // namespace

TEST_CASE("rule pruning: reachable non-terminals follow the productions from the starts", "[grammar][context-free]") {
  const ContextFreeGrammar grammar = two_level_grammar();
  CHECK(dg::reachable_nonterminals(grammar, {0}) == std::vector<char>{1, 1, 0});
  CHECK(dg::reachable_nonterminals(grammar, {1}) == std::vector<char>{0, 1, 0});
  CHECK(dg::reachable_nonterminals(grammar, {2}) == std::vector<char>{0, 0, 1});
  CHECK(dg::reachable_nonterminals(grammar, {}) == std::vector<char>{0, 0, 0});
}

TEST_CASE("rule pruning: an unreachable non-terminal goes with its productions and the rest are renumbered",
          "[grammar][context-free]") {
  ContextFreeGrammar grammar = two_level_grammar();
  // N3 moved first, so dropping it renumbers the others.
  std::swap(grammar.nonterminals[0], grammar.nonterminals[2]);
  for (ShapeProduction& p : grammar.productions) p.lhs = p.lhs == 0 ? 2 : p.lhs == 2 ? 0 : p.lhs;
  for (ShapeProduction& p : grammar.productions)
    for (ChildSlot& child : p.children) child.nonterminal = child.nonterminal == 0 ? 2 : child.nonterminal;
  grammar.axiom.children[0].nonterminal = 2;
  CHECK(dg::drop_unreachable_nonterminals(grammar) == 1);
  REQUIRE(grammar.nonterminals.size() == 2);
  CHECK(grammar.nonterminals[0].name == "N1");
  CHECK(grammar.nonterminals[1].name == "N2");
  CHECK(sites(grammar) == std::vector<std::size_t>{10, 11, 12, 13});
  // The old N1 (index 2) is now index 1, the old N2 (index 1) index 0.
  CHECK(grammar.axiom.children[0].nonterminal == 1);
  CHECK(grammar.axiom.children[0].original_production == 0);
  CHECK(grammar.productions[0].lhs == 1);
  CHECK(grammar.productions[0].children[0].nonterminal == 0);
  CHECK(grammar.productions[0].children[0].original_production == 2);
  CHECK(dg::drop_unreachable_nonterminals(grammar) == 0);
}

TEST_CASE("rule pruning: alternatives that move the model go unless they keep its box and vary inside",
          "[grammar][context-free]") {
  using dg::SwapMotion;
  SECTION("a swap that varies the model keeps every production") {
    ContextFreeGrammar grammar = two_level_grammar();
    CHECK(dg::drop_alternatives_moving_the_model(grammar, {SwapMotion::none, SwapMotion::none, SwapMotion::none}) == 0);
    CHECK(sites(grammar) == std::vector<std::size_t>{10, 11, 12, 13, 14});
  }
  SECTION("moved off its box: the alternative goes although N2 below it has a choice") {
    ContextFreeGrammar grammar = two_level_grammar();
    CHECK(dg::drop_alternatives_moving_the_model(grammar, {SwapMotion::elsewhere, SwapMotion::none, SwapMotion::none}) == 1);
    CHECK(sites(grammar) == std::vector<std::size_t>{10, 12, 13, 14});
    // Slots keep naming the same productions under their new numbers.
    CHECK(grammar.productions[0].children[0].original_production == 1);
    CHECK(grammar.axiom.children[0].original_production == 0);
  }
  SECTION("moved onto its own box: the alternative stays while a choice lies below it") {
    ContextFreeGrammar grammar = two_level_grammar();
    CHECK(dg::drop_alternatives_moving_the_model(grammar, {SwapMotion::in_place, SwapMotion::none, SwapMotion::none}) == 0);
    CHECK(sites(grammar) == std::vector<std::size_t>{10, 11, 12, 13, 14});
  }
  SECTION("moved onto its own box with nothing to vary below: the leaf alternative goes") {
    ContextFreeGrammar grammar = two_level_grammar();
    CHECK(dg::drop_alternatives_moving_the_model(grammar, {SwapMotion::none, SwapMotion::in_place, SwapMotion::none}) == 1);
    CHECK(sites(grammar) == std::vector<std::size_t>{10, 11, 12, 14});
    CHECK(grammar.nonterminals.size() == 3);  // non-terminals stay
  }
}
