// Open L-systems in the grammar core: the cut symbol, single rewriting steps with provenance,
// and derivation with an environment that answers query modules.

#include "grammar/derivation.h"
#include "grammar/lsystem_text.h"
#include "grammar/open_lsystem.h"
#include "grammar/rule_syntax.h"

#include <catch2/catch.hpp>

namespace {

std::vector<dg::Module> modules(const std::string& text) { return dg::parse_axiom(text); }

// Answers ?E(...) with the number of F modules before it in the string (a stand-in for a
// distance the environment measures), counting how often it was asked.
struct CountingEnvironment : dg::QueryEnvironment {
  int answered = 0;
  void answer(std::vector<dg::Module>& string, const std::vector<char>& fresh) override {
    int drawn = 0;
    for (std::size_t i = 0; i < string.size(); ++i) {
      if (string[i].symbol == "F") ++drawn;
      if (string[i].symbol == "?E" && fresh[i]) {
        string[i].parameters.insert(string[i].parameters.begin(), drawn);
        ++answered;
      }
    }
  }
};

}  // namespace

TEST_CASE("cut is one symbol and removes the rest of its branch", "[growth][grammar]") {
  const std::vector<dg::Module> parsed = modules("F cut F");
  REQUIRE(parsed.size() == 3);
  CHECK(parsed[1].symbol == "cut");
  // c u t written apart stay three symbols after a round trip.
  const std::vector<dg::Module> letters{{"c", {}}, {"u", {}}, {"t", {}}};
  CHECK(modules(dg::format_modules(letters)) == letters);
  CHECK(modules("cut[F]").size() == 4);
  CHECK(modules("cutF").size() == 4);  // a letter right after it: c u t F
  CHECK(modules("cut2").front().symbol == "c");

  std::vector<dg::Module> string = modules("F[+F cut F[G]F]F cut F[F]");
  std::vector<std::size_t> origins(string.size());
  for (std::size_t i = 0; i < origins.size(); ++i) origins[i] = i;
  std::vector<char> fresh(string.size(), 1);
  CHECK(dg::apply_cuts(string, &origins, &fresh) == 11);
  CHECK(dg::format_modules(string) == "F[+F]F");
  CHECK(origins == std::vector<std::size_t>{0, 1, 2, 3, 10, 11});
  CHECK(fresh.size() == 6);
}

TEST_CASE("a rewriting step reports where every module comes from and whether it is new", "[growth][grammar]") {
  const dg::LSystem system = dg::parse_lsystem_text("axiom: A B A\nA -> F A\nB -> ε\n", "step.ls");
  const dg::Rewriter rewriter(system);
  dg::Random random(1);
  std::vector<dg::Module> out;
  std::vector<std::size_t> origins;
  std::vector<char> fresh;
  std::vector<dg::Module> axiom = system.axiom;
  CHECK(rewriter.step(axiom, random, out, &origins, &fresh, 100, 1));
  CHECK(dg::format_modules(out) == "FAFA");
  CHECK(origins == std::vector<std::size_t>{0, 0, 2, 2});
  CHECK(fresh == std::vector<char>{1, 1, 1, 1});
  out.clear();
  origins.clear();
  fresh.clear();
  const dg::LSystem inert = dg::parse_lsystem_text("axiom: G F\nA -> F\n", "inert.ls");
  std::vector<dg::Module> inert_axiom = inert.axiom;
  CHECK_FALSE(dg::Rewriter(inert).step(inert_axiom, random, out, &origins, &fresh, 100, 1));
  CHECK(fresh == std::vector<char>{0, 0});
}

TEST_CASE("derive_open answers each query once, when it appears, and rules read the answers", "[growth][grammar]") {
  // Grow until the environment reports three drawn segments before the query, then cut.
  const dg::LSystem system = dg::parse_lsystem_text(
      "axiom: [ ?E ] G\n?E(n) : n < 3 -> F ?E\n?E(n) : n >= 3 -> cut X\nG -> G\n", "open.ls");
  CountingEnvironment environment;
  dg::DerivationOptions options;
  options.limits.max_steps = 50;
  CHECK_THROWS_AS(dg::derive_open(system, environment, options), dg::LimitError);  // G -> G never ends

  const dg::LSystem ending = dg::parse_lsystem_text(
      "axiom: [ ?E ] G\n?E(n) : n < 3 -> F ?E\n?E(n) : n >= 3 -> cut X\n", "open.ls");
  CountingEnvironment counting;
  const dg::Derivation derived = dg::derive_open(ending, counting, options);
  CHECK(dg::format_modules(derived.modules) == "[FFF]G");
  CHECK(counting.answered == 4);  // ?E with 0, 1, 2 and 3 segments before it
  CHECK(derived.steps == 4);
}
