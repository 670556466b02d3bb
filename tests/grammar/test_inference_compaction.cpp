// Instance tree, turtle string and repeated-block compaction on drawings made in code, and the
// whole pixel path on pictures rendered by the engine (drawings that are not in the corpus).

#include "tests/grammar/inference_measure.h"

#include "grammar/compaction.h"
#include "grammar/derivation.h"
#include "grammar/inference_drawing.h"
#include "grammar/inference_pixels.h"
#include "grammar/instance_tree.h"
#include "grammar/lsystem_text.h"
#include "grammar/turtle_string.h"
#include "synthesis/render.h"
#include "synthesis/turtle.h"

#include <catch2/catch.hpp>

namespace {

dg::Drawing draw(const std::string& text) {
  const dg::LSystem system = dg::parse_lsystem_text(text, "test");
  return dg::interpret(dg::derive(system).modules, dg::turtle_options(system.turtle));
}

std::vector<dg::TreeSegment> segments_of(const dg::Drawing& drawing) {
  std::vector<dg::TreeSegment> segments;
  for (const dg::Stroke& stroke : drawing.strokes) {
    const auto lines = dg::flatten_path(stroke.path, 1.0);
    segments.push_back({lines.front().front(), lines.front().back()});
  }
  return segments;
}

}  // namespace

TEST_CASE("compaction: blocks, elided blocks and the shortest grammar", "[pixel][grammar]") {
  CHECK(dg::elide_trailing_branches("FF[+F][-F]") == "FF[+F]-F");
  CHECK(dg::elide_trailing_branches("F[+F[-F]]") == "F+F-F");
  CHECK(dg::replace_blocks("F[+F]F[+F[+F]F]F[+F]F", "F[+F]F") == std::optional<std::string>("F[+F]F"));
  CHECK_FALSE(dg::replace_blocks("F[+F]FF", "F[+F]F"));
  // h^3(F) for F -> F[+F]F.
  std::string text = "F";
  for (int k = 0; k < 3; ++k) {
    std::string next;
    for (char c : text) next += c == 'F' ? std::string("F[+F]F") : std::string(1, c);
    text = next;
  }
  const dg::CompactGrammar grammar = dg::compact_turtle_string(text);
  CHECK(grammar.axiom == "F");
  CHECK(grammar.successor == "F[+F]F");
  CHECK(grammar.iterations == 3);
  CHECK(grammar.length == 1 + 6 + 4);
}

TEST_CASE("instance tree: D_s is 0 for collinear neighbours and negative for branches", "[pixel][grammar]") {
  const dg::TreeSegment a{{0, 0}, {1, 0}}, b{{1, 0}, {2, 0}}, c{{1, 0}, {1, 1}}, far{{5, 0}, {6, 0}};
  CHECK(dg::normalized_pair_distance(a, b) == Approx(0).margin(1e-12));
  CHECK(dg::normalized_pair_distance(a, c) == Approx(-1).margin(1e-12));  // cos 90 - 1
  CHECK(dg::normalized_pair_distance(a, far) == Approx(8));
  // Reversed input segments are oriented away from the root when undirected.
  dg::InstanceTreeOptions options;
  options.directed = false;
  const dg::InstanceTree tree = dg::build_instance_tree({a, {{2, 0}, {1, 0}}, {{1, 1}, {1, 0}}}, 0, false, options);
  REQUIRE(tree.nodes.size() == 3);
  CHECK(tree.unreached == 0);
  CHECK(tree.nodes[1].start.isApprox(dg::Vec2(1, 0)));
  CHECK(tree.nodes[2].start.isApprox(dg::Vec2(1, 0)));
}

TEST_CASE("instance tree: own vector drawings re-derive with their rule", "[pixel][grammar]") {
  // A plant and a Koch island drawn here (not corpus files), as an SVG of their segments.
  for (const std::string text : {"axiom: F\nangle: 30\nstep: 24\nheading: 90\niterations: 3\nF -> F[+F]F[-F]F\n",
                                 "axiom: F-F-F-F\nangle: 90\nstep: 12\niterations: 2\nF -> F+F-F-FF+F+F-F\n"}) {
    const std::vector<dg::TreeSegment> segments = segments_of(draw(text));
    const auto inferred = dg::infer_segment_lsystem(segments, true);
    REQUIRE(inferred);
    INFO(inferred->text);
    const dg::LSystem truth = dg::parse_lsystem_text(text, "truth");
    CHECK(inferred->lsystem.productions == truth.productions);
    CHECK(inferred->lsystem.axiom == truth.axiom);
    CHECK(*inferred->lsystem.turtle.angle_deg == Approx(*truth.turtle.angle_deg).margin(0.01));
  }
}

TEST_CASE("pixel inference: own pictures rendered by the engine", "[pixel][grammar]") {
  // A Koch island (segments) and a window grid (motifs), rasterized at 512 px.
  const std::string koch = "axiom: F-F-F-F\nangle: 90\nstep: 12\niterations: 2\nF -> F+F-F-FF+F+F-F\n";
  const dg::PixelInference island = dg::infer_pixel_lsystem(dg::rasterize(draw(koch)));
  INFO(island.inferred.text);
  CHECK(island.inferred.method == "instance tree");
  CHECK(dg::format_modules(island.inferred.lsystem.axiom) == "F-F-F-F");
  REQUIRE(island.inferred.lsystem.productions.size() == 1);
  CHECK(*island.inferred.lsystem.turtle.angle_deg == Approx(90).margin(1.0));

  const std::string grid =
      "axiom: P1(5)\nmotif A: M 0 0 L 10 0 L 10 8 L 0 8 Z\nP0(m) : m>0 -> A f(16) P0(m-1)\nP0(m) : m==0 -> ε\n"
      "P1(m) : m>0 -> [P0(7)] +(90) f(14) -(90) P1(m-1)\nP1(m) : m==0 -> ε\n";
  const dg::PixelInference windows = dg::infer_pixel_lsystem(dg::rasterize(draw(grid)));
  INFO(windows.inferred.text);
  CHECK(windows.front_end.components >= 35);  // a window may leave a stray pixel group at its start corner
  CHECK(windows.inferred.lsystem.productions.size() == 4);  // two sequence rules with their ε rules
  REQUIRE(windows.inferred.lsystem.turtle.angle_deg);
  CHECK(*windows.inferred.lsystem.turtle.angle_deg == Approx(90).margin(1.0));
}
