// Vector inference building blocks: turtle transforms, mean shift, element similarity, inverse
// instancing, and whole inferences of small synthetic drawings (sequence, linear change, grid,
// branching, segments), including order independence and the command line.

#include "geometry/errors.h"
#include "geometry/svg_reader.h"
#include "grammar/derivation.h"
#include "grammar/grammar_length.h"
#include "grammar/inference.h"
#include "grammar/inference_mean_shift.h"
#include "grammar/inference_terminals.h"
#include "grammar/inference_transform.h"
#include "grammar/lsystem_text.h"
#include "synthesis/turtle.h"
#include "support/cli_run.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

using namespace dg;

namespace {

// The drawing an L-system text makes, as SVG elements (y down), one per stroke.
SvgDrawing draw(const std::string& text) {
  const LSystem system = parse_lsystem_text(text, "test");
  const Drawing drawing = interpret(derive(system).modules, turtle_options(system.turtle));
  SvgDrawing svg;
  for (const Stroke& stroke : drawing.strokes) {
    SvgElement element{"path", 0, {}};
    for (const auto& line : flatten_path(stroke.path, 0.05)) {
      std::vector<Vec2> down;
      for (const Vec2& p : line) down.emplace_back(p.x() + 100, 300 - p.y());
      element.polylines.push_back(std::move(down));
    }
    svg.elements.push_back(std::move(element));
  }
  return svg;
}

// Largest distance from a stroke point of `a` to the nearest of `b` (both in SVG coordinates).
double drawing_distance(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  double worst = 0;
  for (const Vec2& p : a) {
    double best = 1e300;
    for (const Vec2& q : b) best = std::min(best, (p - q).norm());
    worst = std::max(worst, best);
  }
  return worst;
}

std::vector<Vec2> points_of(const SvgDrawing& d) {
  std::vector<Vec2> out;
  for (const auto& e : d.elements)
    for (const auto& line : e.polylines) out.insert(out.end(), line.begin(), line.end());
  return out;
}

std::vector<Vec2> rederived(const InferredLSystem& inferred) {
  const Drawing drawing = interpret(derive(inferred.lsystem).modules, turtle_options(inferred.lsystem.turtle));
  std::vector<Vec2> out;
  for (const Stroke& s : drawing.strokes)
    for (const auto& line : flatten_path(s.path, 0.05))
      for (const Vec2& p : line) out.emplace_back(inferred.start_svg.x() + p.x(), inferred.start_svg.y() - p.y());
  return out;
}

double symmetric_distance(const SvgDrawing& input, const InferredLSystem& inferred) {
  const std::vector<Vec2> a = points_of(input), b = rederived(inferred);
  return std::max(drawing_distance(a, b), drawing_distance(b, a));
}

ElementShape leaf(const Vec2& at, double angle_deg, double scale) {
  const Path2d path = parse_svg_path("M 0 0 C 3 6 11 7 16 0 C 11 -3 4 -3 0 0 Z");
  const Eigen::Rotation2Dd r(angle_deg * 3.14159265358979323846 / 180);
  ElementShape shape;
  for (const auto& line : flatten_path(path, 0.05)) {
    std::vector<Vec2> mapped;
    for (const Vec2& p : line) mapped.push_back(at + scale * (r * p));
    shape.push_back(std::move(mapped));
  }
  return shape;
}

}  // namespace

TEST_CASE("inference: turtle transforms between frames", "[grammar][inference]") {
  const InstanceFrame a{Vec2(1, 2), 30, 2};
  const InstanceFrame b{Vec2(5, -1), -100, 0.5};
  const TurtleTransform t = relative_transform(a, b);
  CHECK(t[1] == Approx(2.5));  // world distance 5, in A's units (scale 2)
  CHECK(t[2] == Approx(0.25));
  const InstanceFrame c = apply_transform(a, t);
  CHECK((c.position - b.position).norm() < 1e-9);
  CHECK(c.angle_deg == Approx(b.angle_deg));
  CHECK(c.scale == Approx(b.scale));
  // Straight ahead: +(0) f(10) *(1) +(8.5)
  const TurtleTransform ahead = relative_transform(InstanceFrame{}, InstanceFrame{Vec2(10, 0), 8.5, 1});
  CHECK(ahead[0] == Approx(0).margin(1e-12));
  CHECK(ahead[3] == Approx(8.5));
  CHECK(transform_command_count(ahead, {}) == 2);
  CHECK(wrap_degrees(540) == 180);
  CHECK(wrap_degrees(-190) == Approx(170));
}

TEST_CASE("inference: mean shift finds clusters, periodic coordinates wrap", "[grammar][inference]") {
  std::vector<ShiftPoint> points;
  for (int k = 0; k < 20; ++k) points.push_back({0.05 * (k % 5), 10 + 0.03 * k, 0, 0});
  for (int k = 0; k < 10; ++k) points.push_back({50 + 0.01 * k, -5, 0, 0});
  points.push_back({200, 200, 0, 0});
  const ShiftClusters c = mean_shift(points, 2, {0, 0, 0, 0});
  REQUIRE(c.centers.size() == 3);
  CHECK(c.sizes[0] == 20);
  CHECK(c.sizes[1] == 10);
  CHECK(c.labels[0] == 0);
  CHECK(c.labels[25] == 1);
  // Angles near 0 and near the period end are one cluster.
  const ShiftClusters w = mean_shift({{0.1, 0, 0, 0}, {179.9, 0, 0, 0}, {0.2, 0, 0, 0}}, 1, {180, 0, 0, 0});
  REQUIRE(w.centers.size() == 1);
  CHECK(w.sizes[0] == 3);
}

TEST_CASE("inference: element similarity ignores position, rotation and scale", "[grammar][inference]") {
  const ElementShape a = leaf(Vec2(0, 0), 0, 1);
  CHECK(element_similarity(a, leaf(Vec2(40, 7), 73, 0.4)) > 0.9);
  ElementShape square{{Vec2(0, 0), Vec2(10, 0), Vec2(10, 10), Vec2(0, 10), Vec2(0, 0)}};
  CHECK(element_similarity(a, square) < 0.6);
  ElementShape circle;
  circle.emplace_back();
  for (int k = 0; k <= 64; ++k) circle.back().emplace_back(std::cos(k * 0.09817477), std::sin(k * 0.09817477));
  CHECK(element_similarity(square, circle) < 0.6);
}

TEST_CASE("inference: inverse instancing groups similar elements with their frames", "[grammar][inference]") {
  std::vector<ElementShape> elements{leaf(Vec2(0, 0), 0, 1), leaf(Vec2(30, 5), 45, 0.5),
                                     ElementShape{{Vec2(0, 0), Vec2(10, 0), Vec2(10, 10), Vec2(0, 10), Vec2(0, 0)}},
                                     ElementShape{{Vec2(3, 3), Vec2(5, 3)}}, ElementShape{{Vec2(7, 7)}}};
  const Instancing result = inverse_instancing(elements);
  CHECK(result.skipped == 1);
  REQUIRE(result.terminals.size() == 3);
  REQUIRE(result.instances.size() == 4);
  std::vector<std::size_t> leaf_terminals;
  for (const TerminalInstance& i : result.instances) {
    const Terminal& t = result.terminals[i.terminal];
    if (t.segment) {
      CHECK(t.symbol == "F");
      CHECK(t.step == Approx(2));
      CHECK(i.frame.angle_deg == Approx(0).margin(1e-9));
    }
    if (i.element == 1) {
      CHECK(i.frame.angle_deg == Approx(45).margin(0.05));
      CHECK(i.frame.scale == Approx(0.5).epsilon(0.002));
      CHECK((i.frame.position - Vec2(30, 5)).norm() < 1e-9);
    }
    if (i.element <= 1) leaf_terminals.push_back(i.terminal);
  }
  REQUIRE(leaf_terminals.size() == 2);
  CHECK(leaf_terminals[0] == leaf_terminals[1]);
}

TEST_CASE("inference: a sequence with a linearly changing step", "[grammar][inference]") {
  const SvgDrawing input = draw("axiom: P(30)\nP(m) : m>0 -> A f(10+0.5*m) +(12) P(m-1)\nP(m) : m==0 -> ε\n");
  const InferredLSystem inferred = infer_lsystem(input);
  INFO(inferred.text);
  CHECK(inferred.rules == 1);
  CHECK(grammar_length(inferred.lsystem) <= 9);
  CHECK(symmetric_distance(input, inferred) < 0.05);
}

TEST_CASE("inference: a grid becomes nested sequences", "[grammar][inference]") {
  const SvgDrawing input = draw(
      "axiom: P1(4)\nmotif A: M 0 0 L 9 0 L 9 7 L 0 7 Z\nP0(m) : m>0 -> A f(13) P0(m-1)\nP0(m) : m==0 -> ε\n"
      "P1(m) : m>0 -> [P0(5)] +(90) f(10) -(90) P1(m-1)\nP1(m) : m==0 -> ε\n");
  const InferredLSystem inferred = infer_lsystem(input);
  INFO(inferred.text);
  CHECK(inferred.rules == 2);
  CHECK(grammar_length(inferred.lsystem) <= 19 + 2);
  CHECK(symmetric_distance(input, inferred) < 0.05);
}

TEST_CASE("inference: branching of segments with scale", "[grammar][inference]") {
  const SvgDrawing input = draw("axiom: X(5)\nheading: 90\nstep: 20\nX(m) : m>0 -> F [+(30) *(0.7) X(m-1)] -(30) *(0.7) X(m-1)\n");
  const InferredLSystem inferred = infer_lsystem(input);
  INFO(inferred.text);
  CHECK(inferred.rules == 1);
  CHECK(symmetric_distance(input, inferred) < 0.05);
  CHECK(inferred.lsystem.turtle.angle_deg.value_or(0) == Approx(30).margin(0.05));
  CHECK(inferred.lsystem.turtle.scale.value_or(0) == Approx(0.7).margin(0.001));
}

TEST_CASE("inference: two terminals are joined by a pair rule", "[grammar][inference]") {
  const SvgDrawing input = draw(
      "axiom: P(10)\nheading: 90\nstep: 20\nP(m) : m>0 -> F [+(40) *(0.8) A] -(5) P(m-1)\nP(m) : m==0 -> ε\n");
  const InferredLSystem inferred = infer_lsystem(input);
  INFO(inferred.text);
  CHECK(inferred.terminals == 2);
  REQUIRE(inferred.lsystem.axiom.size() == 1);  // everything ends in one element
  CHECK(inferred.text.find("Q0 -> ") != std::string::npos);
  CHECK(symmetric_distance(input, inferred) < 0.05);
}

TEST_CASE("inference: element order and weights", "[grammar][inference]") {
  SvgDrawing input = draw("axiom: P(25)\nP(m) : m>0 -> A f(20) *(0.97) +(10) P(m-1)\nP(m) : m==0 -> ε\n");
  const std::string original = infer_lsystem(input).text;
  std::mt19937 random(3);
  std::shuffle(input.elements.begin(), input.elements.end(), random);
  CHECK(infer_lsystem(input).text == original);
  InferenceOptions options;
  options.clusters.weights = ImportanceWeights{0, 1, 0, 0};
  const InferredLSystem by_proximity = infer_lsystem(input, options);
  CHECK(symmetric_distance(input, by_proximity) < 0.05);
}

TEST_CASE("inference: a drawing without extent is an input error", "[grammar][inference]") {
  CHECK_THROWS_AS(infer_lsystem(SvgDrawing{}), InputError);
  SvgDrawing dots;
  dots.elements.push_back(SvgElement{"path", 1, {{Vec2(1, 1)}}});
  CHECK_THROWS_AS(infer_lsystem(dots), InputError);
}

TEST_CASE("inference: dockgrammar lsystem infer", "[grammar][inference][cli]") {
  namespace fs = std::filesystem;
  const fs::path folder = dg::test::fresh_folder("dg_infer_cli");
  {
    std::ofstream svg(folder / "row.svg");
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\">\n<g transform=\"translate(5 5)\">\n";
    for (int k = 0; k < 6; ++k) svg << "<rect x=\"" << 12 * k << "\" y=\"0\" width=\"9\" height=\"7\"/>\n";
    svg << "</g>\n</svg>\n";
    std::ofstream bad(folder / "bad.svg");
    bad << "<svg>\n<path d=\"M 0 0 L\"/>\n</svg>\n";
  }
  const std::string cli = DOCKGRAMMAR_CLI;
  const std::string out = (folder / "row.ls").string();
  CHECK(std::system((cli + " lsystem infer " + (folder / "row.svg").string() + " -o " + out + " --json > " +
                     (folder / "row.json").string()).c_str()) == 0);
  const LSystem written = read_lsystem_text(out);
  CHECK(written.axiom.size() == 1);
  const std::string json = read_text_file(folder / "row.json");
  CHECK(json.find("\"grammar_length\"") != std::string::npos);
  CHECK(json.find("\"timings_s\"") != std::string::npos);
  const int status = std::system((cli + " lsystem infer " + (folder / "bad.svg").string() + " 2> " +
                                  (folder / "err.txt").string()).c_str());
  CHECK(WEXITSTATUS(status) == 2);
  CHECK(read_text_file(folder / "err.txt").find("bad.svg:2: path data") != std::string::npos);
}
