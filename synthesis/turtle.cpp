#include "synthesis/turtle.h"

#include "geometry/errors.h"
#include "geometry/random.h"
#include "synthesis/segment2d.h"

#include <algorithm>
#include <array>
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
  // `A` is the leaf motif unless the system declares it a drawing symbol.
  const bool a_draws = std::find(options.draw_symbols.begin(), options.draw_symbols.end(), "A") != options.draw_symbols.end();
  if (!settings.motifs.count("A") && !a_draws) options.motifs["A"] = parse_svg_path(default_motif);
  for (const auto& [symbol, data] : settings.motifs) {
    try {
      options.motifs[symbol] = parse_svg_path(data);
    } catch (const InputError& error) {
      throw InputError("motif " + symbol + ": " + error.what());
    }
  }
  return options;
}

namespace {

// What the turtle does with a symbol.
enum class TurtleAction : char { Other, Motif, Draw, Move, Left, Right, Around, Scale, Push, Pop };

// Actions of one-character symbols, looked up by byte (most symbols are one character).
struct ActionTable {
  std::array<TurtleAction, 128> action{};
  std::array<const Path2d*, 128> motif{};
};

TurtleAction action_of(const std::string& symbol, const TurtleOptions& options, const Path2d*& motif) {
  if (const auto found = options.motifs.find(symbol); found != options.motifs.end()) {
    motif = &found->second;
    return TurtleAction::Motif;
  }
  if (symbol == "f") return TurtleAction::Move;
  if (std::find(options.draw_symbols.begin(), options.draw_symbols.end(), symbol) != options.draw_symbols.end())
    return TurtleAction::Draw;
  if (symbol == "+") return TurtleAction::Left;
  if (symbol == "-") return TurtleAction::Right;
  if (symbol == "|") return TurtleAction::Around;
  if (symbol == "*") return TurtleAction::Scale;
  if (symbol == "[") return TurtleAction::Push;
  if (symbol == "]") return TurtleAction::Pop;
  return TurtleAction::Other;
}

ActionTable action_table(const TurtleOptions& options) {
  ActionTable table;
  for (int c = 33; c < 127; ++c) table.action[c] = action_of(std::string(1, static_cast<char>(c)), options, table.motif[c]);
  return table;
}

}  // namespace

TurtlePose walk_turtle(const std::vector<Module>& modules, const TurtleOptions& options, const TurtlePose& start,
                       const TurtleVisitor& visitor) {
  Random random(options.seed);
  auto jitter_factor = [&] { return options.jitter_scale > 0 ? 1 + random.uniform(-1, 1) * options.jitter_scale : 1.0; };
  auto jitter_angle = [&] { return options.jitter_angle_deg > 0 ? random.uniform(-1, 1) * options.jitter_angle_deg : 0.0; };
  const ActionTable table = action_table(options);
  TurtlePose state = start;
  std::vector<TurtlePose> stack;
  double direction_heading = start.heading_deg;  // heading_vector(direction_heading) == direction
  Vec2 direction = heading_vector(direction_heading);
  for (std::size_t i = 0; i < modules.size(); ++i) {
    const Module& module = modules[i];
    const std::string& symbol = module.symbol;
    const Path2d* motif = nullptr;
    const auto byte = static_cast<unsigned char>(symbol[0]);
    TurtleAction action;
    if (symbol.size() == 1 && byte < 128) {
      action = table.action[byte];
      motif = table.motif[byte];
    } else {
      action = action_of(symbol, options, motif);
    }
    if (visitor.before) visitor.before(i, state);
    switch (action) {
      case TurtleAction::Motif: {
        const double size = state.scale * jitter_factor();
        if (visitor.motif) visitor.motif(i, *motif, state, size);
        break;
      }
      case TurtleAction::Draw:
      case TurtleAction::Move: {
        const double length = (module.parameters.empty() ? options.step : module.parameters.front()) * state.scale;
        const Vec2 from = state.position;
        if (state.heading_deg != direction_heading) {
          direction_heading = state.heading_deg;
          direction = heading_vector(direction_heading);
        }
        state.position += direction * length * jitter_factor();
        if (action == TurtleAction::Draw && visitor.segment) visitor.segment(i, from, state.position);
        break;
      }
      case TurtleAction::Left:
        state.heading_deg += argument_or(module, options.angle_deg, i, "angle") + jitter_angle();
        break;
      case TurtleAction::Right:
        state.heading_deg -= argument_or(module, options.angle_deg, i, "angle") + jitter_angle();
        break;
      case TurtleAction::Around:
        state.heading_deg += 180;
        break;
      case TurtleAction::Scale:
        state.scale *= argument_or(module, options.scale, i, "scale") * jitter_factor();
        break;
      case TurtleAction::Push:
        stack.push_back(state);
        break;
      case TurtleAction::Pop:
        if (stack.empty()) throw InputError("module " + std::to_string(i) + ": ']' without a matching '['");
        state = stack.back();
        stack.pop_back();
        break;
      case TurtleAction::Other:
        if (visitor.other) visitor.other(i, state);
        break;
    }
  }
  return state;
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
