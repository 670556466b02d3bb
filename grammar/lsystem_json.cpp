#include "grammar/lsystem_json.h"

#include "grammar/lsystem_text.h"
#include "grammar/rule_syntax.h"

#include <cmath>

namespace dg {

namespace {

using Json = nlohmann::ordered_json;

[[noreturn]] void fail(const std::string& source, const std::string& problem) {
  throw InputError(source + ": " + problem);
}

std::optional<double> optional_number(const Json& object, const char* key, const std::string& source) {
  const auto it = object.find(key);
  if (it == object.end() || it->is_null()) return std::nullopt;
  if (!it->is_number() || !std::isfinite(it->get<double>())) fail(source, std::string("\"") + key + "\" must be a number");
  return it->get<double>();
}

const std::string& string_field(const Json& value, const std::string& what, const std::string& source) {
  if (!value.is_string()) fail(source, what + " must be a string");
  return value.get_ref<const std::string&>();
}

void read_rule(const std::string& left, const Json& right, LSystem& system, const std::string& source) {
  const std::string where = "rule \"" + left + "\"";
  Production base;
  try {
    parse_left_side(left, base);
  } catch (const ExpressionSyntaxError& error) {
    fail(source, where + ": column " + std::to_string(error.column) + ": " + error.problem);
  }
  std::vector<const Json*> alternatives;
  if (right.is_array()) {
    if (right.empty()) fail(source, where + ": the list of alternatives is empty");
    for (const Json& alternative : right) alternatives.push_back(&alternative);
  } else {
    alternatives.push_back(&right);
  }
  for (const Json* alternative : alternatives) {
    const std::string& text = string_field(*alternative, where + ": the successor", source);
    Production production = base;
    try {
      parse_right_side(text, production);
    } catch (const ExpressionSyntaxError& error) {
      fail(source, where + ": successor \"" + text + "\": column " + std::to_string(error.column) + ": " + error.problem);
    }
    system.productions.push_back(std::move(production));
  }
}

// Fills turtle settings from a corpus case's "symbols", "motif" and "turtle" fields.
void read_corpus_turtle(const Json& json, TurtleSettings& turtle, const std::string& source) {
  const auto symbols = json.find("symbols");
  if (symbols != json.end() && symbols->is_object()) {
    for (const auto& [symbol, description] : symbols->items()) {
      if (!description.is_string() || !is_symbol_name(symbol)) continue;
      const std::string& text = description.get_ref<const std::string&>();
      if (text.rfind("draw", 0) == 0) turtle.draw_symbols.push_back(symbol);
      if (text.rfind("place one copy of motif", 0) == 0) {
        const auto motif = json.find("motif");
        if (motif == json.end() || !motif->is_object() || !motif->contains("local_path"))
          fail(source, "symbol " + symbol + " places a motif but \"motif.local_path\" is missing");
        turtle.motifs[symbol] = string_field(motif->at("local_path"), "\"motif.local_path\"", source);
      }
    }
  }
  const auto start = json.find("turtle");
  if (start != json.end() && start->is_object()) turtle.heading_deg = optional_number(*start, "start_heading_deg", source);
}

}  // namespace

LSystem lsystem_from_json(const Json& json, const std::string& source) {
  if (!json.is_object()) fail(source, "expected a JSON object with \"axiom\" and \"rules\"");
  if (json.contains("lsystem")) {
    LSystem system = lsystem_from_json(json.at("lsystem"), source);
    read_corpus_turtle(json, system.turtle, source);
    return system;
  }
  LSystem system;
  if (!json.contains("axiom")) fail(source, "missing \"axiom\"");
  const std::string& axiom = string_field(json.at("axiom"), "\"axiom\"", source);
  try {
    system.axiom = parse_axiom(axiom);
  } catch (const ExpressionSyntaxError& error) {
    fail(source, "axiom \"" + axiom + "\": column " + std::to_string(error.column) + ": " + error.problem);
  }
  const auto rules = json.find("rules");
  if (rules != json.end()) {
    if (!rules->is_object()) fail(source, "\"rules\" must be an object {\"predecessor\": \"successor\"}");
    for (const auto& [left, right] : rules->items()) read_rule(left, right, system, source);
  }
  if (const std::optional<double> n = optional_number(json, "iterations", source)) {
    if (*n < 0 || *n != std::floor(*n) || *n > 1e9) fail(source, "\"iterations\" must be a whole number >= 0");
    system.iterations = static_cast<int>(*n);
  }
  TurtleSettings& turtle = system.turtle;
  turtle.angle_deg = optional_number(json, "angle", source);
  turtle.scale = optional_number(json, "scale", source);
  turtle.step = optional_number(json, "step", source);
  turtle.heading_deg = optional_number(json, "heading", source);
  if (const auto draw = json.find("draw"); draw != json.end()) {
    if (!draw->is_array()) fail(source, "\"draw\" must be an array of symbols");
    for (const Json& symbol : *draw) {
      const std::string& name = string_field(symbol, "\"draw\" entries", source);
      if (!is_symbol_name(name)) fail(source, "\"draw\": '" + name + "' is not a symbol name");
      turtle.draw_symbols.push_back(name);
    }
  }
  if (const auto motifs = json.find("motifs"); motifs != json.end()) {
    if (!motifs->is_object()) fail(source, "\"motifs\" must be an object {\"A\": \"M 0 0 L 10 0\"}");
    for (const auto& [symbol, path] : motifs->items()) {
      if (!is_symbol_name(symbol)) fail(source, "\"motifs\": '" + symbol + "' is not a symbol name");
      turtle.motifs[symbol] = string_field(path, "\"motifs\" entries", source);
    }
  }
  return system;
}

LSystem read_lsystem_json(const std::filesystem::path& path) {
  const std::string text = read_text_file(path);
  Json json;
  try {
    json = Json::parse(text);
  } catch (const nlohmann::json::parse_error& error) {
    fail(path.string(), std::string("malformed JSON: ") + error.what());
  }
  return lsystem_from_json(json, path.string());
}

Json lsystem_to_json(const LSystem& system) {
  Json json;
  json["axiom"] = format_modules(system.axiom);
  Json rules = Json::object();
  for (const Production& production : system.productions) {
    const std::string left = format_left_side(production);
    const std::string right = format_right_side(production, "");
    if (!rules.contains(left)) {
      rules[left] = right;
    } else {
      Json& slot = rules[left];
      if (!slot.is_array()) slot = Json::array({slot});
      slot.push_back(right);
    }
  }
  json["rules"] = std::move(rules);
  if (system.iterations) json["iterations"] = *system.iterations;
  const TurtleSettings& turtle = system.turtle;
  auto number_or_null = [](const std::optional<double>& value) { return value ? Json(*value) : Json(nullptr); };
  json["angle"] = number_or_null(turtle.angle_deg);
  json["scale"] = number_or_null(turtle.scale);
  json["scale_ratio"] = turtle.scale && *turtle.scale != 0 ? Json(1.0 / *turtle.scale) : Json(nullptr);
  json["step"] = number_or_null(turtle.step);
  if (turtle.heading_deg) json["heading"] = *turtle.heading_deg;
  if (!turtle.draw_symbols.empty()) json["draw"] = turtle.draw_symbols;
  if (!turtle.motifs.empty()) {
    Json motifs = Json::object();
    for (const auto& [symbol, path] : turtle.motifs) motifs[symbol] = path;
    json["motifs"] = std::move(motifs);
  }
  return json;
}

}  // namespace dg
