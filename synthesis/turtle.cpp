#include "synthesis/turtle.h"

#include "geometry/errors.h"
#include "grammar/random.h"
#include "synthesis/segment2d.h"

#include <algorithm>
#include <cmath>

namespace dg {

namespace {

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

void walk_turtle(const std::vector<Module>& modules, const TurtleOptions& options, const TurtlePose& start,
                 const TurtleVisitor& visitor) {
  Random random(options.seed);
  auto jitter_factor = [&] { return options.jitter_scale > 0 ? 1 + random.uniform(-1, 1) * options.jitter_scale : 1.0; };
  auto jitter_angle = [&] { return options.jitter_angle_deg > 0 ? random.uniform(-1, 1) * options.jitter_angle_deg : 0.0; };
  TurtlePose state = start;
  std::vector<TurtlePose> stack;
  for (std::size_t i = 0; i < modules.size(); ++i) {
    const Module& module = modules[i];
    const std::string& symbol = module.symbol;
    if (const auto motif = options.motifs.find(symbol); motif != options.motifs.end()) {
      const double size = state.scale * jitter_factor();
      if (visitor.motif) visitor.motif(i, motif->second, state, size);
    } else if (symbol == "f" ||
               std::find(options.draw_symbols.begin(), options.draw_symbols.end(), symbol) != options.draw_symbols.end()) {
      const double length = (module.parameters.empty() ? options.step : module.parameters.front()) * state.scale;
      const Vec2 from = state.position;
      state.position += heading_vector(state.heading_deg) * length * jitter_factor();
      if (symbol != "f" && visitor.segment) visitor.segment(i, from, state.position);
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
    } else if (visitor.other) {
      const double ahead = visitor.other(i, state);
      if (ahead != 0) state.position += heading_vector(state.heading_deg) * ahead;
    }
  }
}

Drawing interpret(const std::vector<Module>& modules, const TurtleOptions& options) {
  Drawing drawing;
  TurtleVisitor visitor;
  visitor.segment = [&](std::size_t index, const Vec2& from, const Vec2& to) {
    Path2d segment;
    segment.commands.push_back({PathCommand::Type::Move, {from, Vec2::Zero(), Vec2::Zero()}});
    segment.commands.push_back({PathCommand::Type::Line, {to, Vec2::Zero(), Vec2::Zero()}});
    drawing.strokes.push_back({std::move(segment), index});
  };
  visitor.motif = [&](std::size_t index, const Path2d& motif, const TurtlePose& pose, double size) {
    drawing.strokes.push_back({place_motif(motif, pose, size), index});
  };
  TurtlePose start;
  start.heading_deg = options.heading_deg;
  walk_turtle(modules, options, start, visitor);
  return drawing;
}

Path2d place_motif(const Path2d& motif, const TurtlePose& pose, double size) {
  const Vec2 axis = heading_vector(pose.heading_deg) * size;
  const double c = axis.x(), s = axis.y();
  const Vec2 origin = pose.position;
  return map_path(motif, [&](const Vec2& p) {
    return Vec2(origin.x() + c * p.x() - s * p.y(), origin.y() + s * p.x() + c * p.y());
  });
}

}  // namespace dg
