#include "grammar/lsystem_text.h"

#include "grammar/rule_syntax.h"

#include <catch2/catch.hpp>

#include <string>

namespace {

const char* helix_text = R"(# Št'ava 2010 Fig. 9a
axiom: P(336)
angle: 8.5   // headline angle
scale: 0.993
P(m) : m>0 -> A f(27.5) *(0.993) +(8.5) P(m-1)
P(m) : m==0 -> ε
)";

}  // namespace

TEST_CASE("the text form parses parametric productions", "[grammar]") {
  const dg::LSystem system = dg::parse_lsystem_text(helix_text, "helix.ls");
  REQUIRE(system.axiom.size() == 1);
  CHECK(system.axiom[0] == dg::Module{"P", {336}});
  CHECK(system.turtle.angle_deg == 8.5);
  CHECK(system.turtle.scale == 0.993);
  REQUIRE(system.productions.size() == 2);
  const dg::Production& p = system.productions[0];
  CHECK(p.predecessor == "P");
  CHECK(p.formals == std::vector<std::string>{"m"});
  REQUIRE(p.condition);
  CHECK(dg::format_expression(*p.condition) == "m>0");
  REQUIRE(p.successor.size() == 5);
  CHECK(p.successor[1].symbol == "f");
  CHECK(dg::format_expression(p.successor[4].arguments[0]) == "m-1");
  CHECK(system.productions[1].successor.empty());
}

TEST_CASE("the text form reads string rules, stochastic weights and turtle settings", "[grammar]") {
  const dg::LSystem system = dg::parse_lsystem_text(
      "axiom: F-F\r\nangle: 90\nstep: 10\nheading: 90\niterations: 4\ndraw: F L R\nmotif A: M 0 0 L 9 0\n"
      "F -> (0.25) F[+F]F\nF -> (0.75) F[-F]F\nP0(m, n) : m>0 && n<3 -> P0(m-1, n+1) A\nX ->\n",
      "mixed.ls");
  CHECK(system.axiom.size() == 3);
  CHECK(system.iterations == 4);
  CHECK(system.turtle.heading_deg == 90);
  CHECK(system.turtle.draw_symbols == std::vector<std::string>{"F", "L", "R"});
  CHECK(system.turtle.motifs.at("A") == "M 0 0 L 9 0");
  REQUIRE(system.productions.size() == 4);
  CHECK(system.productions[0].probability == 0.25);
  CHECK(dg::format_successor(system.productions[1].successor) == "F[-F]F");
  CHECK(system.productions[2].predecessor == "P0");
  CHECK(system.productions[2].formals == std::vector<std::string>{"m", "n"});
  CHECK(system.productions[3].successor.empty());
  CHECK(dg::parse_lsystem_text("\xEF\xBB\xBF" "axiom: F\n", "bom.ls").axiom.size() == 1);
}

TEST_CASE("printing the text form and parsing it again gives the same system", "[grammar]") {
  for (const std::string& text :
       {std::string(helix_text),
        std::string("axiom: R(4)\nR(m) : m>0 -> A [-(17) f(64) *(0.8) -(3) R(m-1)] [+(7) f(181) *(0.6) +(23) R(m-1)]\n"
                    "R(m) : m==0 -> A\n"),
        std::string("axiom: X\nangle: 25.7\nstep: 8\nheading: 90\niterations: 5\nX -> F[+X][-X]FX\nF -> FF\n"),
        std::string("axiom: F 0 F0 ?X(1)\nF -> (0.5) F[+F]F\nF -> (0.5) ε\ndraw: L R\nmotif B: M 0 0 C 1 2 3 4 5 6 Z\n"
                    "Q(a,b) : !(a<b) || b==-1 -> Q(a^2, -b*(a+1)) B(pi)\n")}) {
    const dg::LSystem first = dg::parse_lsystem_text(text, "a.ls");
    const std::string printed = dg::format_lsystem_text(first);
    INFO(printed);
    CHECK(dg::parse_lsystem_text(printed, "b.ls") == first);
  }
}

TEST_CASE("text form errors name the file, line and column", "[grammar]") {
  auto message = [](const std::string& text) {
    try {
      dg::parse_lsystem_text(text, "plant.ls");
    } catch (const dg::InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  CHECK(message("axiom: F\nF -> F[+F(]") == "plant.ls:2: column 10: '(' is never closed");
  CHECK(message("axiom: F\n\nP(m) : n>0 -> A") == "plant.ls:3: column 8: 'n' is not a parameter of P(m)");
  CHECK(message("axiom: F\nP(m) -> A(k)") == "plant.ls:2: column 11: 'k' is not a parameter of P(m)");
  CHECK(message("angle: 90") == "plant.ls: no axiom (add a line like 'axiom: F')");
  CHECK(message("axiom: F\nangel: 90").rfind("plant.ls:2: unknown setting 'angel'", 0) == 0);
  CHECK(message("axiom: F\nangle: 90\nangle: 30") == "plant.ls:3: angle is given twice");
  CHECK(message("axiom: P(m)") == "plant.ls:1: column 10: the axiom cannot use the name 'm'");
  CHECK(message("axiom: F\nF -> (0) F") == "plant.ls:2: column 6: the probability must be a positive number");
  CHECK(message("axiom: F\nF F -> F") == "plant.ls:2: column 3: unexpected 'F' after the predecessor");
  CHECK(message("axiom: F\nF -> F ε") == "plant.ls:2: column 8: 'ε' must stand alone (it is the empty successor)");
  CHECK(message("axiom: F\nF") == "plant.ls:2: expected 'setting: value' or a production 'predecessor -> successor'");
  CHECK(message("axiom: F\niterations: 2.5") == "plant.ls:2: iterations must be a whole number >= 0");
  CHECK_THROWS_WITH(dg::read_lsystem_text("/nonexistent/x.ls"), "/nonexistent/x.ls: cannot read");
}
