#include "synthesis/turtle.h"

#include "geometry/errors.h"
#include "grammar/random.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dg {

namespace {

struct TurtleState {
  Vec2 position = Vec2::Zero();
  double heading_deg = 0;
  double scale = 1;
};

Vec2 direction(double heading_deg) {
  const double radians = heading_deg * std::numbers::pi / 180.0;
  return Vec2(std::cos(radians), std::sin(radians));
}

double argument_or(const Module& module, const std::optional<double>& fallback, std::size_t index,
                   const char* setting) {
  if (!module.parameters.empty()) return module.parameters.front();
  if (!fallback)
    throw InputError("module " + std::to_string(index) + " '" + module.symbol + "' has no argument and the L-system sets no " +
                     setting + " (add a line '" + setting + ": ...')");
  return *fallback;
}

}  // namespace

TurtleOptions turtle_options(const TurtleSettings& settings) {
  TurtleOptions options;
  options.angle_deg = settings.angle_deg;
  options.scale = settings.scale;
  if (settings.step) options.step = *settings.step;
  if (settings.heading_deg) options.heading_deg = *settings.heading_deg;
  if (!settings.draw_symbols.empty()) options.draw_symbols = settings.draw_symbols;
  if (!settings.motifs.count("A")) options.motifs["A"] = parse_svg_path(default_motif);
  for (const auto& [symbol, data] : settings.motifs) {
    try {
      options.motifs[symbol] = parse_svg_path(data);
    } catch (const InputError& error) {
      throw InputError("motif " + symbol + ": " + error.what());
    }
  }
  return options;
}

Drawing interpret(const std::vector<Module>& modules, const TurtleOptions& options) {
  Drawing drawing;
  Random random(options.seed);
  auto jitter_factor = [&] { return options.jitter_scale > 0 ? 1 + random.uniform(-1, 1) * options.jitter_scale : 1.0; };
  auto jitter_angle = [&] { return options.jitter_angle_deg > 0 ? random.uniform(-1, 1) * options.jitter_angle_deg : 0.0; };
  TurtleState state;
  state.heading_deg = options.heading_deg;
  std::vector<TurtleState> stack;
  for (std::size_t i = 0; i < modules.size(); ++i) {
    const Module& module = modules[i];
    const std::string& symbol = module.symbol;
    if (const auto motif = options.motifs.find(symbol); motif != options.motifs.end()) {
      const double size = state.scale * jitter_factor();
      const double radians = state.heading_deg * std::numbers::pi / 180.0;
      const double c = std::cos(radians) * size, s = std::sin(radians) * size;
      const Vec2 origin = state.position;
      drawing.strokes.push_back({map_path(motif->second,
                                          [&](const Vec2& p) {
                                            return Vec2(origin.x() + c * p.x() - s * p.y(),
                                                        origin.y() + s * p.x() + c * p.y());
                                          }),
                                 i});
    } else if (symbol == "f" ||
               std::find(options.draw_symbols.begin(), options.draw_symbols.end(), symbol) != options.draw_symbols.end()) {
      const double length = (module.parameters.empty() ? options.step : module.parameters.front()) * state.scale;
      const Vec2 start = state.position;
      state.position += direction(state.heading_deg) * length * jitter_factor();
      if (symbol != "f") {
        Path2d segment;
        segment.commands.push_back({PathCommand::Type::Move, {start, Vec2::Zero(), Vec2::Zero()}});
        segment.commands.push_back({PathCommand::Type::Line, {state.position, Vec2::Zero(), Vec2::Zero()}});
        drawing.strokes.push_back({std::move(segment), i});
      }
    } else if (symbol == "+") {
      state.heading_deg += argument_or(module, options.angle_deg, i, "angle") + jitter_angle();
    } else if (symbol == "-") {
      state.heading_deg -= argument_or(module, options.angle_deg, i, "angle") + jitter_angle();
    } else if (symbol == "|") {
      state.heading_deg += 180;
    } else if (symbol == "*") {
      state.scale *= argument_or(module, options.scale, i, "scale") * jitter_factor();
    } else if (symbol == "[") {
      stack.push_back(state);
    } else if (symbol == "]") {
      if (stack.empty()) throw InputError("module " + std::to_string(i) + ": ']' without a matching '['");
      state = stack.back();
      stack.pop_back();
    }
  }
  return drawing;
}

}  // namespace dg
