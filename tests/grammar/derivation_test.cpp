#include "grammar/derivation.h"

#include "grammar/grammar_length.h"
#include "grammar/lsystem_text.h"
#include "grammar/symbol_replacement.h"

#include <catch2/catch.hpp>

#include <string>

namespace {

dg::LSystem parse(const std::string& text) { return dg::parse_lsystem_text(text, "test.ls"); }

std::size_t count_symbol(const std::vector<dg::Module>& modules, const std::string& symbol) {
  std::size_t n = 0;
  for (const dg::Module& module : modules) n += module.symbol == symbol;
  return n;
}

}  // namespace

TEST_CASE("string rules rewrite all modules in parallel", "[grammar]") {
  const dg::LSystem algae = parse("axiom: A\nA -> AB\nB -> A\n");
  dg::DerivationOptions options;
  options.steps = 5;
  const dg::Derivation d = dg::derive(algae, options);
  CHECK(dg::format_modules(d.modules) == "ABAABABAABAAB");
  CHECK(d.steps == 5);
  options.steps = 0;
  CHECK(dg::format_modules(dg::derive(algae, options).modules) == "A");
}

TEST_CASE("paper 000's helix derives 336 leaves and stops by itself", "[grammar]") {
  const dg::LSystem helix =
      parse("axiom: P(336)\nP(m) : m>0 -> A f(27.5) *(0.993) +(8.5) P(m-1)\nP(m) : m==0 -> ε\n");
  const dg::Derivation d = dg::derive(helix);
  CHECK(d.steps == 337);
  CHECK(d.modules.size() == 1344);
  CHECK(count_symbol(d.modules, "A") == 336);
  CHECK(count_symbol(d.modules, "P") == 0);
  CHECK(d.modules[1] == dg::Module{"f", {27.5}});
  CHECK(dg::grammar_length(helix) == 11);
}

TEST_CASE("arguments are evaluated with the formals bound", "[grammar]") {
  const dg::LSystem linear = parse("axiom: P(3)\nP(m) : m>0 -> f(8+0.25*m) P(m-1)\n");
  const dg::Derivation d = dg::derive(linear);
  REQUIRE(d.modules.size() == 4);
  CHECK(d.modules[0].parameters[0] == 8.75);
  CHECK(d.modules[2].parameters[0] == 8.25);
  CHECK(d.modules[3] == dg::Module{"P", {0}});  // no production applies: kept (implicit identity rule)
  CHECK(d.steps == 3);
  const dg::LSystem arity = parse("axiom: P(1,2) P(3)\nP(a) -> X\n");  // P(1,2) has the wrong arity
  CHECK(dg::format_modules(dg::derive(arity).modules) == "P(1,2) X");
}

TEST_CASE("stochastic derivation is reproducible per seed", "[grammar]") {
  const dg::LSystem system = parse("axiom: F\nF -> (1) F[+F]F\nF -> (1) F[-F]F\nF -> (2) FF\n");
  dg::DerivationOptions options;
  options.steps = 5;
  options.seed = 7;
  const std::string first = dg::format_modules(dg::derive(system, options).modules);
  CHECK(dg::format_modules(dg::derive(system, options).modules) == first);
  options.seed = 8;
  CHECK(dg::format_modules(dg::derive(system, options).modules) != first);
  // All three alternatives occur, roughly in proportion to their weights.
  options.steps = 1;
  int counts[3] = {0, 0, 0};
  for (std::uint64_t seed = 0; seed < 400; ++seed) {
    options.seed = seed;
    const std::string s = dg::format_modules(dg::derive(system, options).modules);
    ++counts[s == "F[+F]F" ? 0 : s == "F[-F]F" ? 1 : 2];
  }
  CHECK(counts[0] > 60);
  CHECK(counts[1] > 60);
  CHECK(counts[2] > 150);
}

TEST_CASE("stochastic choice only among productions whose condition holds", "[grammar]") {
  const dg::LSystem system = parse("axiom: P(0) P(5)\nP(m) : m>0 -> (0.5) A\nP(m) : m>0 -> (0.5) B\nP(m) : m==0 -> C\n");
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    dg::DerivationOptions options;
    options.seed = seed;
    options.steps = 1;
    const std::string s = dg::format_modules(dg::derive(system, options).modules);
    CHECK((s == "CA" || s == "CB"));
  }
}

TEST_CASE("derivation limits end runaway grammars", "[grammar]") {
  const dg::LSystem doubling = parse("axiom: F\nF -> FF\n");
  dg::DerivationOptions options;
  options.steps = 30;
  options.limits.max_modules = 1000;
  CHECK_THROWS_AS(dg::derive(doubling, options), dg::LimitError);
  CHECK_THROWS_WITH(dg::derive(doubling, options),
                    "derivation exceeds 1000 modules at step 10; raise --max-modules or use fewer iterations");
  options.steps.reset();
  options.limits.max_modules = 100000;
  options.limits.max_steps = 50;
  const dg::LSystem endless = parse("axiom: P(0)\nP(m) -> P(m+1)\n");
  CHECK_THROWS_WITH(dg::derive(endless, options), Catch::StartsWith("derivation still rewrites after 50 steps"));
  const dg::LSystem division = parse("axiom: P(0)\nP(m) -> f(1/m)\n");
  CHECK_THROWS_AS(dg::derive(division), dg::InputError);
}

TEST_CASE("symbol replacement edits the axiom and successors", "[grammar]") {
  dg::LSystem grid = parse("axiom: P1(2)\nP0(m) : m>0 -> A f(13) P0(m-1)\nP1(m) : m>0 -> [P0(3)] +(90) f(10) -(90) P1(m-1)\n");
  CHECK(dg::replace_symbol(grid, "P0", "A") == 2);
  const dg::Derivation d = dg::derive(grid);
  CHECK(count_symbol(d.modules, "A") == 2);
  CHECK(dg::replace_symbol(grid, "Q", "A") == 0);
}
