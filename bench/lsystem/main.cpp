// Bench of the L-system inference: drawings of 100 to 5,000 elements are made by the L-system
// engine (a window grid, a branching tree of leaves, a spiral of leaves with a linearly changing
// step, a bracketed plant of segments, the dragon curve with two drawing letters, a plant with a
// non-drawing apex X -> F[+X][-X]FX, F -> FF), then inferred from vectors (Št'ava et al. 2010; the plant
// through the instance tree of Guo et al. 2020 when that is shorter); Koch islands and window
// grids are also rasterized and inferred from pixels. Prints one line per drawing: kind,
// elements, seconds, method, grammar length. Usage: dockgrammar-bench-lsystem [--quick]

#include "geometry/svg_reader.h"
#include "geometry/errors.h"
#include "grammar/derivation.h"
#include "grammar/grammar_length.h"
#include "grammar/inference.h"
#include "grammar/inference_drawing.h"
#include "grammar/inference_pixels.h"
#include "grammar/lsystem_text.h"
#include "synthesis/render.h"
#include "synthesis/turtle.h"

#include <fmt/core.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

// The drawing an L-system makes, as SVG elements (y down), one per stroke.
dg::SvgDrawing draw(const std::string& text) {
  const dg::LSystem system = dg::parse_lsystem_text(text, "bench");
  const dg::Derivation derivation = dg::derive(system);
  const dg::Drawing drawing = dg::interpret(derivation.modules, dg::turtle_options(system.turtle));
  dg::SvgDrawing svg;
  for (const dg::Stroke& stroke : drawing.strokes) {
    dg::SvgElement element{"path", 0, {}};
    for (const auto& line : dg::flatten_path(stroke.path, 0.02)) {
      std::vector<dg::Vec2> down;
      for (const dg::Vec2& p : line) down.emplace_back(p.x(), -p.y());
      element.polylines.push_back(std::move(down));
    }
    svg.elements.push_back(std::move(element));
  }
  return svg;
}

void run(const std::string& kind, const std::string& text) {
  const dg::SvgDrawing drawing = draw(text);
  const dg::InferredLSystem inferred = dg::infer_lsystem(drawing);
  fmt::print("{:<10} {:>6} elements  {:>8.3f} s  (instancing {:.3f} s, rules {:.3f} s)  {:>4} rules  grammar length {}\n", kind,
             drawing.elements.size(), inferred.timings.total_s, inferred.timings.instancing_s, inferred.timings.rules_s,
             inferred.rules, dg::grammar_length(inferred.lsystem));
}

// The instance-tree-or-vector choice of `lsystem infer DRAWING.svg`.
void run_choice(const std::string& kind, const std::string& text) {
  const dg::SvgDrawing drawing = draw(text);
  const dg::InferredLSystem inferred = dg::infer_drawing_lsystem(drawing);
  fmt::print("{:<10} {:>6} elements  {:>8.3f} s  ({})  grammar length {}\n", kind, drawing.elements.size(), inferred.timings.total_s,
             inferred.comparison, dg::grammar_length(inferred.lsystem));
}

// `lsystem infer PICTURE.png` on the drawing rasterized with the given long side.
void run_pixels(const std::string& kind, const std::string& text, int long_side_px) {
  const dg::LSystem system = dg::parse_lsystem_text(text, "bench");
  const dg::Drawing drawing = dg::interpret(dg::derive(system).modules, dg::turtle_options(system.turtle));
  dg::RenderOptions render;
  render.long_side_px = long_side_px;
  const dg::Image image = dg::rasterize(drawing, render);
  dg::PixelInference result;
  try {
    result = dg::infer_pixel_lsystem(image);
  } catch (const dg::InputError& error) {
    fmt::print("{:<10} {:>6} elements  no result ({}x{} px): {}\n", kind, drawing.strokes.size(), image.width, image.height, error.what());
    return;
  }
  fmt::print("{:<10} {:>6} elements  {:>8.3f} s  (front end {:.3f} s, {}x{} px, {} pieces; {})  grammar length {}\n", kind,
             drawing.strokes.size(), result.inferred.timings.total_s, result.front_end.seconds, image.width, image.height,
             result.front_end.pieces, result.inferred.comparison, dg::grammar_length(result.inferred.lsystem));
}

std::string koch_island(int iterations) {
  return fmt::format("axiom: F-F-F-F\nangle: 90\nstep: 12\niterations: {}\nF -> F+F-F-FF+F+F-F\n", iterations);
}

std::string grid(int rows, int columns) {
  return fmt::format(
      "axiom: P1({})\nmotif A: M 0 0 L 9 0 L 9 7 L 0 7 Z\n"
      "P0(m) : m>0 -> A f(13) P0(m-1)\nP0(m) : m==0 -> ε\n"
      "P1(m) : m>0 -> [P0({})] +(90) f(10) -(90) P1(m-1)\nP1(m) : m==0 -> ε\n",
      rows, columns);
}

std::string tree(int depth) {
  return fmt::format(
      "axiom: R({})\nR(m) : m>0 -> A [-(17) f(64) *(0.8) -(3) R(m-1)] [+(7) f(181) *(0.6) +(23) R(m-1)]\n"
      "R(m) : m==0 -> A\n",
      depth);
}

std::string spiral(int count) {
  return fmt::format("axiom: P({})\nP(m) : m>0 -> A f(20+0.05*m) +(3) P(m-1)\nP(m) : m==0 -> ε\n", count);
}

std::string plant(int iterations) {
  return fmt::format("axiom: F\nangle: 25.7\nstep: 10\nheading: 90\niterations: {}\nF -> F[+F]F[-F]F\n", iterations);
}

std::string dragon(int iterations) {
  return fmt::format("axiom: L\nangle: 90\nstep: 10\ndraw: L R\niterations: {}\nL -> L+R+\nR -> -L-R\n", iterations);
}

std::string apex_plant(int iterations) {
  return fmt::format("axiom: X\nangle: 25.7\nstep: 8\nheading: 90\niterations: {}\nX -> F[+X][-X]FX\nF -> FF\n", iterations);
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::string(argv[1]) == "--quick";
  for (const auto& [rows, columns] : std::vector<std::pair<int, int>>{{10, 10}, {20, 25}, {32, 37}, {40, 50}, {50, 100}})
    if (!quick || rows * columns <= 1184) run("grid", grid(rows, columns));
  for (int depth : {5, 7, 9, 10, 11, 12})
    if (!quick || depth <= 9) run("tree", tree(depth));
  for (int count : {100, 500, 1184, 2000, 5000})
    if (!quick || count <= 1184) run("spiral", spiral(count));
  for (int iterations : {3, 4, 5})
    if (!quick || iterations <= 4) run("plant", plant(iterations));
  for (int iterations : {3, 4, 5, 6})
    if (!quick || iterations <= 5) run_choice("plant-tree", plant(iterations));
  for (int iterations : {8, 10, 12})
    if (!quick || iterations <= 10) run_choice("dragon", dragon(iterations));
  for (int iterations : {4, 5, 6, 7})
    if (!quick || iterations <= 6) run_choice("apex-plant", apex_plant(iterations));
  // Pixels: about 10 px per Koch step, 40 px per window column.
  for (int iterations : {1, 2, 3}) run_pixels("koch-px", koch_island(iterations), 24 * (1 << (2 * iterations)) + 64);
  for (const auto& [rows, columns] : std::vector<std::pair<int, int>>{{10, 10}, {20, 25}, {32, 37}})
    run_pixels("grid-px", grid(rows, columns), 40 * columns);
  return 0;
}
