#include "synthesis/turtle.h"

#include "grammar/derivation.h"
#include "grammar/lsystem_text.h"

#include <catch2/catch.hpp>

namespace {

dg::Drawing draw(const std::string& text) {
  const dg::LSystem system = dg::parse_lsystem_text(text, "turtle.ls");
  return dg::interpret(dg::derive(system).modules, dg::turtle_options(system.turtle));
}

dg::Vec2 end_of(const dg::Stroke& stroke) { return stroke.path.commands.back().points[0]; }

}  // namespace

TEST_CASE("the turtle draws, turns and moves with the corpus conventions", "[synthesis]") {
  const dg::Drawing d = draw("axiom: F+F-(45)f(2)F\nangle: 90\nstep: 10\n");
  REQUIRE(d.strokes.size() == 3);
  CHECK(end_of(d.strokes[0]).isApprox(dg::Vec2(10, 0)));
  CHECK(end_of(d.strokes[1]).isApprox(dg::Vec2(10, 10)));  // + turns left (counter-clockwise, y up)
  const dg::Vec2 start = d.strokes[2].path.commands[0].points[0];
  CHECK(start.isApprox(dg::Vec2(10 + std::sqrt(2.0), 10 + std::sqrt(2.0))));
  CHECK(d.strokes[2].module_index == 5);
  const dg::Drawing back = draw("axiom: F|F\n");  // | turns around
  CHECK((end_of(back.strokes[1]) - dg::Vec2(0, 0)).norm() < 1e-12);
}

TEST_CASE("brackets restore position, heading and scale, scale multiplies lengths", "[synthesis]") {
  const dg::Drawing d = draw("axiom: F[+*F]F\nangle: 90\nscale: 0.5\nstep: 4\nheading: 90\n");
  REQUIRE(d.strokes.size() == 3);
  CHECK(end_of(d.strokes[0]).isApprox(dg::Vec2(0, 4)));
  CHECK((end_of(d.strokes[1]) - dg::Vec2(-2, 4)).norm() < 1e-12);
  CHECK((end_of(d.strokes[2]) - dg::Vec2(0, 8)).norm() < 1e-12);
}

TEST_CASE("motif symbols place a scaled, rotated copy of their path", "[synthesis]") {
  const dg::Drawing d = draw("axiom: B *(2) +(90) B L\nmotif B: M 0 0 L 1 0 L 1 1 Z\ndraw: L\n");
  REQUIRE(d.strokes.size() == 3);
  const dg::Path2d& second = d.strokes[1].path;
  REQUIRE(second.commands.size() == 4);
  CHECK((second.commands[1].points[0] - dg::Vec2(0, 2)).norm() < 1e-12);
  CHECK((second.commands[2].points[0] - dg::Vec2(-2, 2)).norm() < 1e-12);
  CHECK(second.commands[3].type == dg::PathCommand::Type::Close);
  CHECK((end_of(d.strokes[2]) - dg::Vec2(0, 2)).norm() < 1e-12);  // L draws like F, step 1 * scale 2
  const dg::Drawing leaf = draw("axiom: A\n");  // A has a default motif
  CHECK(leaf.strokes.size() == 1);
  CHECK(leaf.strokes[0].path.commands.size() > 2);  // the leaf outline, not a segment
  // Declared a drawing symbol, A draws a segment of one step like F.
  const dg::Drawing segments = draw("axiom: A+B\nangle: 90\ndraw: A B\n");
  REQUIRE(segments.strokes.size() == 2);
  CHECK(segments.strokes[0].path.commands.size() == 2);
  CHECK((end_of(segments.strokes[0]) - dg::Vec2(1, 0)).norm() < 1e-12);
  CHECK((end_of(segments.strokes[1]) - dg::Vec2(1, 1)).norm() < 1e-12);
}

TEST_CASE("the turtle reports missing settings and unbalanced brackets", "[synthesis]") {
  CHECK_THROWS_WITH(draw("axiom: F+F\n"), Catch::Contains("sets no angle"));
  CHECK_THROWS_WITH(draw("axiom: F*F\n"), Catch::Contains("sets no scale"));
  CHECK_THROWS_WITH(draw("axiom: F]F\n"), Catch::Contains("']' without a matching '['"));
  CHECK_THROWS_WITH(draw("axiom: A\nmotif A: M 0 0 Q 1 1 2 2\n"), Catch::StartsWith("motif A: path data: unsupported command 'Q'"));
}

TEST_CASE("jitter is seeded: same seed same drawing, other seed other drawing", "[synthesis]") {
  const dg::LSystem system = dg::parse_lsystem_text("axiom: F\nangle: 25\nF -> F[+F]F[-F]F\niterations: 3\n", "j.ls");
  const std::vector<dg::Module> modules = dg::derive(system).modules;
  dg::TurtleOptions options = dg::turtle_options(system.turtle);
  const dg::Vec2 plain = end_of(dg::interpret(modules, options).strokes.back());
  options.jitter_angle_deg = 5;
  options.jitter_scale = 0.1;
  options.seed = 3;
  const dg::Vec2 a = end_of(dg::interpret(modules, options).strokes.back());
  CHECK(a == end_of(dg::interpret(modules, options).strokes.back()));
  options.seed = 4;
  const dg::Vec2 b = end_of(dg::interpret(modules, options).strokes.back());
  CHECK((a - b).norm() > 1e-6);
  CHECK((a - plain).norm() > 1e-6);
}
