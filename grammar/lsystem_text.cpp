#include "grammar/lsystem_text.h"

#include "grammar/rule_syntax.h"

#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

namespace dg {

namespace {

std::string_view trim(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
  return text;
}

// Column (0-based) of `part` inside `line`; both views point into the same buffer.
std::size_t offset_in(std::string_view line, std::string_view part) {
  return static_cast<std::size_t>(part.data() - line.data());
}

struct LineContext {
  const std::string& source;
  std::size_t line_number;

  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(source + ":" + std::to_string(line_number) + ": " + problem);
  }

  // Runs `parse` on `part` of `line`; syntax errors get the line number and a line column.
  template <typename Parse>
  auto guarded(std::string_view line, std::string_view part, Parse parse) const {
    try {
      return parse(part);
    } catch (const ExpressionSyntaxError& error) {
      fail("column " + std::to_string(error.column + offset_in(line, part)) + ": " + error.problem);
    }
  }

  double constant(std::string_view line, std::string_view value, const std::string& key) const {
    return guarded(line, value, [&](std::string_view text) {
      const Expression e = parse_expression(text);
      if (!expression_variables(e).empty()) fail(key + " must be a number");
      const double v = evaluate(e, {}, {});
      if (!std::isfinite(v)) fail(key + " must be finite");
      return v;
    });
  }
};

std::string_view strip_comment(std::string_view line) {
  const std::size_t hash = line.find('#');
  const std::size_t slashes = line.find("//");
  return line.substr(0, std::min(hash, slashes));
}

void set_once(std::optional<double>& slot, double value, const LineContext& context, const std::string& key) {
  if (slot) context.fail(key + " is given twice");
  slot = value;
}

void parse_setting(std::string_view line, std::string_view key, std::string_view value, LSystem& system,
                   bool& has_axiom, const LineContext& context) {
  const std::string name(key);
  TurtleSettings& turtle = system.turtle;
  if (key == "axiom") {
    if (has_axiom) context.fail("axiom is given twice");
    system.axiom = context.guarded(line, value, [](std::string_view text) { return parse_axiom(text); });
    has_axiom = true;
  } else if (key == "angle") {
    set_once(turtle.angle_deg, context.constant(line, value, name), context, name);
  } else if (key == "scale") {
    set_once(turtle.scale, context.constant(line, value, name), context, name);
  } else if (key == "step") {
    set_once(turtle.step, context.constant(line, value, name), context, name);
  } else if (key == "heading") {
    set_once(turtle.heading_deg, context.constant(line, value, name), context, name);
  } else if (key == "iterations") {
    if (system.iterations) context.fail("iterations is given twice");
    const double n = context.constant(line, value, name);
    if (n < 0 || n != std::floor(n) || n > 1e9) context.fail("iterations must be a whole number >= 0");
    system.iterations = static_cast<int>(n);
  } else if (key == "draw") {
    std::istringstream names{std::string(value)};
    std::string symbol;
    while (names >> symbol) {
      if (!is_symbol_name(symbol)) context.fail("'" + symbol + "' is not a symbol name");
      turtle.draw_symbols.push_back(symbol);
    }
    if (turtle.draw_symbols.empty()) context.fail("draw: needs at least one symbol, like draw: F L R");
  } else if (key.substr(0, 6) == "motif ") {
    const std::string symbol(trim(key.substr(6)));
    if (!is_symbol_name(symbol)) context.fail("'motif " + symbol + "': '" + symbol + "' is not a symbol name");
    if (turtle.motifs.count(symbol)) context.fail("motif " + symbol + " is given twice");
    if (value.empty()) context.fail("motif " + symbol + " needs SVG path data, like M 0 0 L 10 0");
    turtle.motifs[symbol] = std::string(value);
  } else {
    context.fail("unknown setting '" + name +
                 "' (expected axiom, angle, scale, step, heading, iterations, draw, motif X, or a production with ->)");
  }
}

}  // namespace

LSystem parse_lsystem_text(std::string_view text, const std::string& source) {
  LSystem system;
  bool has_axiom = false;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte order mark
  std::size_t number = 0;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t newline = text.find('\n', start);
    const std::size_t end = newline == std::string_view::npos ? text.size() : newline;
    std::string_view raw = text.substr(start, end - start);
    start = end + 1;
    ++number;
    if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
    const LineContext context{source, number};
    const std::string_view line = trim(strip_comment(raw));
    if (line.empty()) continue;
    const std::size_t arrow = line.find("->");
    if (arrow != std::string_view::npos) {
      Production production;
      context.guarded(raw, line.substr(0, arrow), [&](std::string_view left) {
        parse_left_side(left, production);
        return 0;
      });
      context.guarded(raw, line.substr(arrow + 2), [&](std::string_view right) {
        parse_right_side(right, production);
        return 0;
      });
      system.productions.push_back(std::move(production));
    } else {
      const std::size_t colon = line.find(':');
      if (colon == std::string_view::npos)
        context.fail("expected 'setting: value' or a production 'predecessor -> successor'");
      parse_setting(raw, trim(line.substr(0, colon)), trim(line.substr(colon + 1)), system, has_axiom, context);
    }
  }
  if (!has_axiom) throw InputError(source + ": no axiom (add a line like 'axiom: F')");
  return system;
}

std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot read");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputError(path.string() + ": cannot read");
  return buffer.str();
}

LSystem read_lsystem_text(const std::filesystem::path& path) {
  return parse_lsystem_text(read_text_file(path), path.string());
}

std::string format_lsystem_text(const LSystem& system) {
  std::string text = "axiom: " + format_modules(system.axiom) + "\n";
  const TurtleSettings& turtle = system.turtle;
  if (turtle.angle_deg) text += "angle: " + format_number(*turtle.angle_deg) + "\n";
  if (turtle.scale) text += "scale: " + format_number(*turtle.scale) + "\n";
  if (turtle.step) text += "step: " + format_number(*turtle.step) + "\n";
  if (turtle.heading_deg) text += "heading: " + format_number(*turtle.heading_deg) + "\n";
  if (system.iterations) text += "iterations: " + std::to_string(*system.iterations) + "\n";
  if (!turtle.draw_symbols.empty()) {
    text += "draw:";
    for (const std::string& symbol : turtle.draw_symbols) text += " " + symbol;
    text += "\n";
  }
  for (const auto& [symbol, path] : turtle.motifs) text += "motif " + symbol + ": " + path + "\n";
  for (const Production& production : system.productions)
    text += format_left_side(production) + " -> " + format_right_side(production, "ε") + "\n";
  return text;
}

}  // namespace dg
