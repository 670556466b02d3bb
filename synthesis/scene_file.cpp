#include "synthesis/scene_file.h"

#include "geometry/errors.h"
#include "grammar/lsystem_text.h"
#include "synthesis/growth.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace dg {

namespace {

using Json = nlohmann::json;

// Errors carry the file and the JSON location ("guides[1].polygon").
struct Reader {
  std::string source;

  [[noreturn]] void fail(const std::string& where, const std::string& problem) const {
    throw InputError(source + ": " + (where.empty() ? "" : where + ": ") + problem);
  }

  const Json& field(const Json& object, const char* key, const std::string& where) const {
    const auto it = object.find(key);
    if (it == object.end()) fail(where, std::string("missing \"") + key + "\"");
    return *it;
  }

  double number(const Json& value, const std::string& where) const {
    if (!value.is_number() || !std::isfinite(value.get<double>())) fail(where, "must be a finite number");
    return value.get<double>();
  }

  double number_or(const Json& object, const char* key, double fallback, const std::string& where) const {
    const auto it = object.find(key);
    return it == object.end() ? fallback : number(*it, where + "." + key);
  }

  std::size_t index(const Json& value, const std::string& where) const {
    const double n = number(value, where);
    if (n < 0 || n != std::floor(n) || n > 1e9) fail(where, "must be a whole number >= 0");
    return static_cast<std::size_t>(n);
  }

  const std::string& text(const Json& value, const std::string& where) const {
    if (!value.is_string()) fail(where, "must be a string");
    return value.get_ref<const std::string&>();
  }

  Vec2 point(const Json& value, const std::string& where) const {
    if (!value.is_array() || value.size() != 2) fail(where, "must be a point [x, y]");
    return Vec2(number(value[0], where + "[0]"), number(value[1], where + "[1]"));
  }

  std::vector<double> numbers(const Json& object, const char* key, const std::string& where) const {
    std::vector<double> values;
    const auto it = object.find(key);
    if (it == object.end()) return values;
    if (!it->is_array()) fail(where + "." + key, "must be an array of numbers");
    for (std::size_t i = 0; i < it->size(); ++i)
      values.push_back(number((*it)[i], where + "." + key + "[" + std::to_string(i) + "]"));
    return values;
  }

  std::size_t guide(const Json& value, const GrowthScene& scene, const std::string& where) const {
    const std::string& name = text(value, where);
    for (std::size_t g = 0; g < scene.guides.size(); ++g)
      if (scene.guides[g].name == name) return g;
    fail(where, "unknown guide '" + name + "'");
  }
};

Json parse_json(const std::string& text, const std::string& source) {
  try {
    return Json::parse(text);
  } catch (const Json::parse_error& error) {
    // nlohmann reports a byte offset; turn it into line and column.
    const std::size_t offset = std::min<std::size_t>(error.byte, text.size());
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i + 1 < offset; ++i) {
      if (text[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    throw InputError(source + ":" + std::to_string(line) + ": column " + std::to_string(column) + ": malformed JSON");
  }
}

void read_lsystems(const Json& json, GrowthScene& scene, const Reader& reader, const std::filesystem::path& folder) {
  const auto it = json.find("lsystems");
  if (it == json.end()) return;
  if (!it->is_object()) reader.fail("lsystems", "must be an object of name: L-system");
  for (const auto& [name, value] : it->items()) {
    const std::string where = "lsystems." + name;
    std::string text;
    std::string source = reader.source + ": " + where;
    if (value.is_string()) {
      text = value.get<std::string>();
    } else if (value.is_array()) {
      for (const Json& line : value) text += reader.text(line, where) + "\n";
    } else if (value.is_object() && value.contains("file")) {
      const std::filesystem::path path = folder / reader.text(value["file"], where + ".file");
      text = read_text_file(path);
      source = path.string();
    } else {
      reader.fail(where, "must be L-system text, an array of lines, or {\"file\": PATH}");
    }
    scene.lsystems.push_back({name, parse_lsystem_text(text, source)});
  }
}

void read_guides(const Json& json, GrowthScene& scene, const Reader& reader) {
  const Json& guides = reader.field(json, "guides", "");
  if (!guides.is_array() || guides.empty()) reader.fail("guides", "must be a non-empty array");
  for (std::size_t g = 0; g < guides.size(); ++g) {
    const std::string where = "guides[" + std::to_string(g) + "]";
    const Json& object = guides[g];
    if (!object.is_object()) reader.fail(where, "must be an object");
    Guide guide;
    guide.name = reader.text(reader.field(object, "id", where), where + ".id");
    for (const Guide& other : scene.guides)
      if (other.name == guide.name) reader.fail(where, "guide id '" + guide.name + "' is used twice");
    const Json& polygon = reader.field(object, "polygon", where);
    if (!polygon.is_array()) reader.fail(where + ".polygon", "must be an array of points");
    for (std::size_t v = 0; v < polygon.size(); ++v)
      guide.polygon.push_back(reader.point(polygon[v], where + ".polygon[" + std::to_string(v) + "]"));
    if (const auto it = object.find("lsystem"); it != object.end()) {
      const std::string& name = reader.text(*it, where + ".lsystem");
      for (std::size_t l = 0; l < scene.lsystems.size(); ++l)
        if (scene.lsystems[l].name == name) guide.lsystem = l;
      if (!guide.lsystem) reader.fail(where + ".lsystem", "unknown L-system '" + name + "'");
    }
    if (const auto it = object.find("seeds"); it != object.end()) {
      if (!it->is_array()) reader.fail(where + ".seeds", "must be an array");
      for (std::size_t s = 0; s < it->size(); ++s) {
        const std::string at = where + ".seeds[" + std::to_string(s) + "]";
        const Json& seed = (*it)[s];
        if (!seed.is_object()) reader.fail(at, "must be an object");
        guide.seeds.push_back({reader.point(reader.field(seed, "position", at), at + ".position"),
                               reader.number_or(seed, "heading", 90, at), reader.numbers(seed, "parameters", at)});
      }
      if (!guide.seeds.empty() && !guide.lsystem) reader.fail(where, "has seeds but no \"lsystem\"");
    }
    scene.guides.push_back(std::move(guide));
  }
}

void read_links(const Json& json, GrowthScene& scene, const Reader& reader) {
  const auto it = json.find("links");
  if (it == json.end()) return;
  if (!it->is_array()) reader.fail("links", "must be an array");
  for (std::size_t l = 0; l < it->size(); ++l) {
    const std::string where = "links[" + std::to_string(l) + "]";
    const Json& object = (*it)[l];
    if (!object.is_object()) reader.fail(where, "must be an object");
    GuideLink link;
    link.from_guide = reader.guide(reader.field(object, "from", where), scene, where + ".from");
    link.from_edge = reader.index(reader.field(object, "from_edge", where), where + ".from_edge");
    link.to_guide = reader.guide(reader.field(object, "to", where), scene, where + ".to");
    link.to_edge = reader.index(reader.field(object, "to_edge", where), where + ".to_edge");
    const double tokens = reader.number_or(object, "tokens", 1, where);
    if (tokens < 0 || tokens != std::floor(tokens) || tokens > 1e9) reader.fail(where + ".tokens", "must be a whole number >= 0");
    link.tokens = static_cast<int>(tokens);
    link.angle_deg = reader.number_or(object, "angle", 0, where);
    if (link.from_edge >= scene.guides[link.from_guide].polygon.size())
      reader.fail(where + ".from_edge", "guide '" + scene.guides[link.from_guide].name + "' has no edge " +
                                            std::to_string(link.from_edge));
    if (link.to_edge >= scene.guides[link.to_guide].polygon.size())
      reader.fail(where + ".to_edge",
                  "guide '" + scene.guides[link.to_guide].name + "' has no edge " + std::to_string(link.to_edge));
    scene.links.push_back(link);
  }
}

std::pair<std::size_t, std::size_t> guide_vertex(const Json& object, const char* guide_key, const char* vertex_key,
                                                 const GrowthScene& scene, const Reader& reader, const std::string& where) {
  const std::size_t guide = reader.guide(reader.field(object, guide_key, where), scene, where + "." + guide_key);
  const std::size_t vertex = reader.index(reader.field(object, vertex_key, where), where + "." + vertex_key);
  if (vertex >= scene.guides[guide].polygon.size())
    reader.fail(where + "." + vertex_key, "guide '" + scene.guides[guide].name + "' has no vertex " + std::to_string(vertex));
  return {guide, vertex};
}

void read_springs(const Json& json, GrowthScene& scene, const Reader& reader) {
  const auto it = json.find("springs");
  if (it == json.end()) return;
  if (!it->is_object()) reader.fail("springs", "must be an object");
  SpringSettings& springs = scene.springs;
  springs.edge_stiffness = reader.number_or(*it, "edge_stiffness", springs.edge_stiffness, "springs");
  springs.diagonal_stiffness = reader.number_or(*it, "diagonal_stiffness", springs.diagonal_stiffness, "springs");
  springs.link_stiffness = reader.number_or(*it, "link_stiffness", springs.link_stiffness, "springs");
  const double iterations = reader.number_or(*it, "iterations", springs.iterations, "springs");
  if (iterations < 1 || iterations > 1e6) reader.fail("springs.iterations", "must be between 1 and 1000000");
  springs.iterations = static_cast<int>(iterations);
  if (const auto rigid = it->find("link_springs"); rigid != it->end()) {
    if (!rigid->is_boolean()) reader.fail("springs.link_springs", "must be true or false");
    springs.link_springs = rigid->get<bool>();
  }
  for (const char* key : {"between", "pinned"}) {
    const auto list = it->find(key);
    if (list == it->end()) continue;
    if (!list->is_array()) reader.fail(std::string("springs.") + key, "must be an array");
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string where = std::string("springs.") + key + "[" + std::to_string(i) + "]";
      const Json& object = (*list)[i];
      if (!object.is_object()) reader.fail(where, "must be an object");
      if (std::string(key) == "pinned") {
        springs.pinned.push_back(guide_vertex(object, "guide", "vertex", scene, reader, where));
      } else {
        const auto [ga, va] = guide_vertex(object, "a", "vertex_a", scene, reader, where);
        const auto [gb, vb] = guide_vertex(object, "b", "vertex_b", scene, reader, where);
        springs.springs.push_back({ga, va, gb, vb});
      }
    }
  }
  if (springs.edge_stiffness < 0 || springs.diagonal_stiffness < 0 || springs.link_stiffness < 0)
    reader.fail("springs", "stiffness values must be >= 0");
}

std::vector<GuideEdit> read_edits(const Json& list, const GrowthScene& scene, const Reader& reader, const std::string& key) {
  std::vector<GuideEdit> edits;
  if (!list.is_array()) reader.fail(key, "must be an array of edits");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string where = key + "[" + std::to_string(i) + "]";
    const Json& object = list[i];
    if (!object.is_object()) reader.fail(where, "must be an object");
    GuideEdit edit;
    edit.guide = reader.guide(reader.field(object, "guide", where), scene, where + ".guide");
    const std::string& op = reader.text(reader.field(object, "op", where), where + ".op");
    if (op == "translate") {
      edit.kind = GuideEdit::Kind::Translate;
      edit.offset = reader.point(reader.field(object, "by", where), where + ".by");
    } else if (op == "rotate") {
      edit.kind = GuideEdit::Kind::Rotate;
      edit.angle_deg = reader.number(reader.field(object, "degrees", where), where + ".degrees");
    } else if (op == "scale") {
      edit.kind = GuideEdit::Kind::Scale;
      edit.factor = reader.number(reader.field(object, "factor", where), where + ".factor");
      if (!(edit.factor > 0)) reader.fail(where + ".factor", "must be positive");
    } else if (op == "move_vertex") {
      edit.kind = GuideEdit::Kind::MoveVertex;
      edit.vertex = guide_vertex(object, "guide", "vertex", scene, reader, where).second;
      edit.offset = reader.point(reader.field(object, "to", where), where + ".to");
    } else if (op == "snap") {
      edit.kind = GuideEdit::Kind::Snap;
      edit.edge = reader.index(reader.field(object, "edge", where), where + ".edge");
      edit.target = reader.guide(reader.field(object, "target", where), scene, where + ".target");
      edit.target_edge = reader.index(reader.field(object, "target_edge", where), where + ".target_edge");
      if (edit.edge >= scene.guides[edit.guide].polygon.size()) reader.fail(where + ".edge", "no such edge");
      if (edit.target_edge >= scene.guides[edit.target].polygon.size()) reader.fail(where + ".target_edge", "no such edge");
      if (edit.target == edit.guide) reader.fail(where, "a guide cannot snap onto itself");
    } else {
      reader.fail(where + ".op", "unknown edit '" + op + "' (expected translate, rotate, scale, move_vertex, snap)");
    }
    edits.push_back(edit);
  }
  return edits;
}

void read_limits(const Json& json, GrowthScene& scene, const Reader& reader) {
  const auto it = json.find("limits");
  if (it == json.end()) return;
  if (!it->is_object()) reader.fail("limits", "must be an object");
  GrowthLimits& limits = scene.limits;
  const double steps = reader.number_or(*it, "max_steps", limits.max_steps, "limits");
  const double elements = reader.number_or(*it, "max_elements", static_cast<double>(limits.max_elements), "limits");
  const double modules = reader.number_or(*it, "max_modules", static_cast<double>(limits.max_modules), "limits");
  if (steps < 1 || steps > 1e7 || elements < 1 || elements > 1e9 || modules < 1 || modules > 1e9)
    reader.fail("limits", "limits must be between 1 and 1e7 steps, 1e9 elements and modules");
  limits.max_steps = static_cast<int>(steps);
  limits.max_elements = static_cast<std::size_t>(elements);
  limits.max_modules = static_cast<std::size_t>(modules);
}

}  // namespace

GrowthScene parse_growth_scene(const std::string& text, const std::string& source, const std::filesystem::path& folder) {
  const Reader reader{source};
  const Json json = parse_json(text, source);
  if (!json.is_object()) reader.fail("", "a scene must be a JSON object with \"guides\"");
  GrowthScene scene;
  read_lsystems(json, scene, reader, folder);
  read_guides(json, scene, reader);
  read_links(json, scene, reader);
  read_springs(json, scene, reader);
  read_limits(json, scene, reader);
  if (const auto it = json.find("edits"); it != json.end()) scene.edits = read_edits(*it, scene, reader, "edits");
  try {
    check_growth_scene(scene);
  } catch (const InputError& error) {
    reader.fail("", error.what());
  }
  return scene;
}

GrowthScene read_growth_scene(const std::filesystem::path& path) {
  return parse_growth_scene(read_text_file(path), path.string(), path.parent_path());
}

std::vector<GuideEdit> read_guide_edits(const std::filesystem::path& path, const GrowthScene& scene) {
  const Reader reader{path.string()};
  const std::string text = read_text_file(path);
  const Json json = parse_json(text, path.string());
  if (json.is_object() && json.contains("edits")) return read_edits(json["edits"], scene, reader, "edits");
  return read_edits(json, scene, reader, "edits");
}

}  // namespace dg
