// Two-letter D0L recovery on unbranched turtle strings: systems derived here by the engine
// (grammar/derivation.h), written as the drawing shows them (every letter an `F`, turns summed),
// must come back as a system that derives the same string and is no longer than the original;
// and the same for plants with a non-drawing apex (X -> u, F -> FF); the whole segment path on
// a dragon curve, a Lévy curve and an apex plant drawn here.

#include "tests/grammar/inference_measure.h"

#include "grammar/d0l_apex.h"
#include "grammar/d0l_chain.h"
#include "grammar/derivation.h"
#include "grammar/grammar_length.h"
#include "grammar/inference_segments.h"
#include "grammar/lsystem_text.h"
#include "grammar/turtle_string.h"
#include "synthesis/turtle.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <string>

namespace {

// The derived string as a drawing shows it: drawing symbols as F, runs of turns by their sum.
std::string drawn_string(const dg::LSystem& system) {
  const std::vector<std::string>& draw = system.turtle.draw_symbols;
  std::string out;
  int turn = 0;
  for (const dg::Module& m : dg::derive(system).modules) {
    if (m.symbol == "+") ++turn;
    else if (m.symbol == "-") --turn;
    else if (std::find(draw.begin(), draw.end(), m.symbol) != draw.end()) {
      out += std::string(static_cast<std::size_t>(std::abs(turn)), turn > 0 ? '+' : '-') + "F";
      turn = 0;
    }
  }
  return out;
}

// The system's drawing as segments (y up) and as an SVG drawing (y down).
std::pair<std::vector<dg::TreeSegment>, dg::SvgDrawing> drawn_segments(const dg::LSystem& system) {
  const dg::Drawing drawing = dg::interpret(dg::derive(system).modules, dg::turtle_options(system.turtle));
  std::vector<dg::TreeSegment> segments;
  dg::SvgDrawing svg;
  for (const dg::Stroke& stroke : drawing.strokes) {
    const auto lines = dg::flatten_path(stroke.path, 1.0);
    const dg::Vec2 a = lines.front().front(), b = lines.front().back();
    segments.push_back({a, b});
    svg.elements.push_back({"path", 0, {{dg::Vec2(a.x(), -a.y()), dg::Vec2(b.x(), -b.y())}}});
  }
  return {segments, svg};
}

// Symmetric Hausdorff distance between the drawing and the inferred system's re-derivation, over
// the drawing's bounding-box diagonal.
double relative_hausdorff(const dg::SvgDrawing& svg, const dg::InferredLSystem& inferred) {
  const double diagonal = dg::test::diagonal_of(dg::test::drawing_points(svg, 1.0));
  const auto input = dg::test::drawing_points(svg, diagonal / 2000);
  const auto output = dg::test::rederived_points(inferred, diagonal / 2000);
  return dg::test::symmetric_hausdorff(input, output, diagonal / 100) / diagonal;
}

dg::LSystem chain_system(const dg::ChainGrammar& g) {
  return dg::parse_lsystem_text("axiom: " + g.axiom + "\ndraw: F G\niterations: " + std::to_string(g.iterations) +
                                    "\nF -> " + g.f_successor + "\nG -> " + g.g_successor + "\n",
                                "recovered");
}

}  // namespace

TEST_CASE("d0l chain: two-letter systems come back from their drawn strings", "[grammar][inference]") {
  // The dragon as in the corpus's source (L, R both draw; turns before and after letters), the
  // dragon's two-symbol form, a system with three letters per block, Sierpiński's arrowhead and
  // the Gosper curve (seven letters per block).
  for (const std::string text : {"axiom: L\ndraw: L R\niterations: 8\nL -> L+R+\nR -> -L-R\n",
                                 "axiom: F\ndraw: F G\niterations: 9\nF -> F+G\nG -> F-G\n",
                                 "axiom: F\ndraw: F G\niterations: 5\nF -> F+G-F\nG -> G--F+G\n",
                                 "axiom: A\ndraw: A B\niterations: 6\nA -> B-A-B\nB -> A+B+A\n",
                                 "axiom: A\ndraw: A B\niterations: 3\nA -> A-B--B+A++AA+B-\nB -> +A-BB--B-A++A+B\n"}) {
    const dg::LSystem truth = dg::parse_lsystem_text(text, "truth");
    const std::string drawn = drawn_string(truth);
    const auto recovered = dg::recover_chain_grammar(drawn);
    INFO(text);
    REQUIRE(recovered);
    INFO(recovered->axiom << " | F -> " << recovered->f_successor << " | G -> " << recovered->g_successor << " | n "
                          << recovered->iterations);
    CHECK(drawn_string(chain_system(*recovered)) == drawn);
    CHECK(recovered->length <= dg::grammar_length(truth));
    CHECK(recovered->length == dg::grammar_length(chain_system(*recovered)));
  }
  // One pattern of inner turns: a one-letter system (the Lévy curve, end to end, below).
  const auto one = dg::recover_chain_grammar("F+F-F+F-F+F-F+F");
  REQUIRE(one);
  CHECK(one->g_successor.empty());
  // Five segments cut into no groups; branches are not chains.
  CHECK_FALSE(dg::recover_chain_grammar("F+F-F++F--F"));
  CHECK_FALSE(dg::recover_chain_grammar("F[+F]F[-F]F"));
}

TEST_CASE("d0l chain: a dragon curve and a Lévy curve drawn here are inferred from their segments", "[grammar][inference]") {
  // The Lévy curve at 45 degrees shows only multiples of 90 (δ = 90): with turns wrapping at 360
  // degrees it is F -> +F-F there; the prefix blocks of the drawing never find it.
  for (const std::string text : {"axiom: L\nangle: 90\nstep: 7\nheading: 30\ndraw: L R\niterations: 9\nL -> L+R+\nR -> -L-R\n",
                                 "axiom: F\nangle: 45\nstep: 5\niterations: 8\nF -> +F--F+\n"}) {
    const dg::LSystem truth = dg::parse_lsystem_text(text, "truth");
    const auto [segments, svg] = drawn_segments(truth);
    const auto inferred = dg::infer_segment_lsystem(segments, true);
    INFO(text);
    REQUIRE(inferred);
    INFO(inferred->text);
    CHECK(inferred->lsystem.productions.size() == truth.productions.size());
    CHECK(dg::grammar_length(inferred->lsystem) <= dg::grammar_length(truth));
    CHECK(relative_hausdorff(svg, *inferred) < 1e-6);
  }
}

TEST_CASE("d0l apex: plants with a non-drawing apex come back from their drawn strings", "[grammar][inference]") {
  // Prusinkiewicz & Lindenmayer Fig. 1.24d, e, f (n = 5, 4, 4): X draws nothing, F -> FF.
  for (const std::string text : {"axiom: X\niterations: 5\nX -> F[+X]F[-X]+X\nF -> FF\n",
                                 "axiom: X\niterations: 4\nX -> F[+X][-X]FX\nF -> FF\n",
                                 "axiom: X\niterations: 4\nX -> F-[[X]+X]+F[+FX]-X\nF -> FF\n"}) {
    const dg::LSystem truth = dg::parse_lsystem_text(text, "truth");
    std::string raw;
    for (const dg::Module& m : dg::derive(truth).modules)
      if (m.symbol != "X") raw += m.symbol;
    INFO(text);
    for (bool descending : {false, true}) {
      const auto drawn = dg::canonical_turtle_string(raw, descending);
      REQUIRE(drawn);
      const auto recovered = dg::recover_apex_grammar(*drawn, descending);
      REQUIRE(recovered);
      INFO("X -> " << recovered->apex_successor << " | m " << recovered->m << " | n " << recovered->iterations);
      const std::string rules = "X -> " + recovered->apex_successor + "\nF -> " + std::string(static_cast<std::size_t>(recovered->m), 'F') + "\n";
      const dg::LSystem again = dg::parse_lsystem_text("axiom: X\niterations: " + std::to_string(recovered->iterations) + "\n" + rules, "recovered");
      std::string raw_again;
      for (const dg::Module& m : dg::derive(again).modules)
        if (m.symbol != "X") raw_again += m.symbol;
      CHECK(dg::canonical_turtle_string(raw_again, descending) == drawn);
      CHECK(recovered->length <= dg::grammar_length(truth));
      CHECK(recovered->length == dg::grammar_length(again));
    }
  }
  // A single-rule plant has no apex copy that ends its branches with whole runs.
  CHECK_FALSE(dg::recover_apex_grammar("F[+F]F[-F]F", false));
}

TEST_CASE("d0l apex: a plant with an apex drawn here is inferred from its segments", "[grammar][inference]") {
  const std::string text = "axiom: X\nangle: 20\nstep: 3\nheading: 80\niterations: 5\nX -> F[+X]F[-X]+X\nF -> FF\n";
  const dg::LSystem truth = dg::parse_lsystem_text(text, "truth");
  const auto [segments, svg] = drawn_segments(truth);
  const auto inferred = dg::infer_segment_lsystem(segments, true);
  REQUIRE(inferred);
  INFO(inferred->text);
  CHECK(dg::grammar_length(inferred->lsystem) <= dg::grammar_length(truth));
  CHECK(*inferred->lsystem.turtle.angle_deg == Approx(20).margin(0.01));
  CHECK(relative_hausdorff(svg, *inferred) < 1e-6);
}
