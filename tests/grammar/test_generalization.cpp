// Rule merging (Guo et al. 2020 §4.3): weighted edit distance and greedy merging into
// stochastic rules, on grammars of the core.

#include "grammar/derivation.h"
#include "grammar/generalization.h"
#include "grammar/grammar_length.h"
#include "grammar/lsystem_text.h"

#include <catch2/catch.hpp>

namespace {

std::vector<dg::SuccessorItem> successor(const std::string& rule) {
  return dg::parse_lsystem_text("axiom: X\nX -> " + rule + "\n", "test").productions.front().successor;
}

}  // namespace

TEST_CASE("generalization: weighted edit distance uses 1.0 / 1.5 / 1.5", "[generalization][grammar]") {
  CHECK(dg::weighted_edit_distance(successor("F+F"), successor("F+F")) == 0);
  CHECK(dg::weighted_edit_distance(successor("F+F"), successor("F-F")) == 1.0);
  CHECK(dg::weighted_edit_distance(successor("F+F"), successor("F+FF")) == 1.5);
  CHECK(dg::weighted_edit_distance(successor("F+FF"), successor("F+F")) == 1.5);
  CHECK(dg::weighted_edit_distance(successor("F[+F]F"), successor("F")) == 7.5);
  CHECK(dg::weighted_edit_distance(successor("f(2)"), successor("f(3)")) == 1.0);
}

TEST_CASE("generalization: identical rules merge at w0 = 0.5, similar ones only with a larger w0", "[generalization][grammar]") {
  const dg::LSystem same = dg::parse_lsystem_text("axiom: A B\nangle: 30\nA -> F[+A]F\nB -> F[+B]F\n", "test");
  const dg::Generalization merged = dg::generalize(same);
  REQUIRE(merged.merges.size() == 1);
  CHECK(merged.merges[0].edit_distance == 0);
  REQUIRE(merged.system.productions.size() == 1);
  CHECK(merged.system.productions[0].probability == Approx(1.0));
  CHECK(dg::grammar_length(merged.system) < dg::grammar_length(same));
  CHECK(dg::format_modules(merged.system.axiom) == "AA");

  const dg::LSystem similar = dg::parse_lsystem_text("axiom: A B\nangle: 30\nA -> F[+A]F\nB -> F[-B]F\n", "test");
  CHECK(dg::generalize(similar).merges.empty());  // cost 0.5 * (-1) + 0.5 * 1.0 = 0: not below 0
  dg::GeneralizationOptions eager;
  eager.w0 = 0.8;
  const dg::Generalization stochastic = dg::generalize(similar, eager);
  REQUIRE(stochastic.merges.size() == 1);
  CHECK(stochastic.merges[0].cost == Approx(0.8 * -1 + 0.2 * 1.0));
  REQUIRE(stochastic.system.productions.size() == 2);
  CHECK(stochastic.system.productions[0].predecessor == stochastic.system.productions[1].predecessor);
  CHECK(stochastic.system.productions[0].probability == Approx(0.5));
  CHECK(stochastic.system.productions[1].probability == Approx(0.5));
  // The merged grammar derives: both alternatives occur over a few seeds.
  bool plus = false, minus = false;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    dg::DerivationOptions options;
    options.steps = 3;
    options.seed = seed;
    const std::string text = dg::format_modules(dg::derive(stochastic.system, options).modules);
    plus = plus || text.find('+') != std::string::npos;
    minus = minus || text.find('-') != std::string::npos;
  }
  CHECK(plus);
  CHECK(minus);
}

TEST_CASE("generalization: rules of different arity are never merged", "[generalization][grammar]") {
  const dg::LSystem system = dg::parse_lsystem_text("axiom: A P(2)\nA -> F A\nP(m) : m>0 -> F P(m-1)\n", "test");
  dg::GeneralizationOptions eager;
  eager.w0 = 1.0;
  CHECK(dg::generalize(system, eager).merges.empty());
}
