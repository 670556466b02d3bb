// Every case of the 2D ground-truth corpus (../shared/corpus/lsystems) re-derived by the engine:
// string lengths, element counts, grammar lengths, and the drawn coordinates against the SVG.

#include "grammar/derivation.h"
#include "grammar/grammar_length.h"
#include "grammar/lsystem_json.h"
#include "grammar/lsystem_text.h"
#include "synthesis/turtle.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

const fs::path corpus_dir = fs::path(DOCKGRAMMAR_SOURCE_DIR) / ".." / "shared" / "corpus" / "lsystems";

// One corpus SVG element: its numbers in order, and whether it is a <polyline>.
struct SvgElement {
  std::vector<double> numbers;
  bool polyline = false;
};

// Test-local reader for the corpus SVGs: one <path d="..."/> or <polyline points="..."/> per line.
std::vector<SvgElement> read_corpus_svg(const fs::path& path) {
  const std::string text = dg::read_text_file(path);
  const std::regex element(R"(<(path|polyline) (?:d|points)="([^"]*)\")");
  const std::regex number(R"([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)");
  std::vector<SvgElement> elements;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), element); it != std::sregex_iterator(); ++it) {
    SvgElement e;
    e.polyline = (*it)[1] == "polyline";
    const std::string data = (*it)[2];
    for (auto n = std::sregex_iterator(data.begin(), data.end(), number); n != std::sregex_iterator(); ++n)
      e.numbers.push_back(std::stod(n->str()));
    elements.push_back(std::move(e));
  }
  return elements;
}

// The numbers the corpus would write for `stroke` (SVG coordinates, y down): every point of the
// path in order; a closed polyline repeats its first point where the path says Z.
std::vector<double> stroke_numbers(const dg::Stroke& stroke, double start_x, double start_y, bool polyline) {
  std::vector<double> numbers;
  auto add = [&](const dg::Vec2& p) {
    numbers.push_back(p.x() + start_x);
    numbers.push_back(start_y - p.y());
  };
  dg::Vec2 first = dg::Vec2::Zero();
  for (const dg::PathCommand& c : stroke.path.commands) {
    switch (c.type) {
      case dg::PathCommand::Type::Move: first = c.points[0]; add(c.points[0]); break;
      case dg::PathCommand::Type::Line: add(c.points[0]); break;
      case dg::PathCommand::Type::Cubic: for (const dg::Vec2& p : c.points) add(p); break;
      case dg::PathCommand::Type::Close: if (polyline) add(first); break;
    }
  }
  return numbers;
}

}  // namespace

TEST_CASE("every corpus case re-derives to its ground truth", "[synthesis][corpus]") {
  if (!fs::is_directory(corpus_dir)) {
    WARN("corpus not found at " << corpus_dir.string() << "; skipped");
    return;
  }
  std::vector<fs::path> cases;
  for (const fs::directory_entry& entry : fs::directory_iterator(corpus_dir))
    if (entry.path().extension() == ".json") cases.push_back(entry.path());
  std::sort(cases.begin(), cases.end());
  REQUIRE_FALSE(cases.empty());
  std::size_t compared = 0;
  for (const fs::path& path : cases) {
    const Json truth = Json::parse(dg::read_text_file(path));
    const std::string id = truth.at("id");
    INFO("case " << id);
    const dg::LSystem system = dg::read_lsystem_json(path);
    CHECK(dg::grammar_length(system) == truth.at("grammar_length").get<std::size_t>());

    const dg::Derivation derivation = dg::derive(system);
    CHECK(derivation.steps == truth.at("lsystem").at("iterations").get<int>());
    CHECK(derivation.modules.size() == truth.at("expanded_string_length").get<std::size_t>());

    const dg::Drawing drawing = dg::interpret(derivation.modules, dg::turtle_options(system.turtle));
    CHECK(drawing.strokes.size() == truth.at("element_count").get<std::size_t>());

    const std::vector<SvgElement> svg = read_corpus_svg(corpus_dir / truth.at("files").at("svg").get<std::string>());
    REQUIRE(svg.size() == truth.at("element_count").get<std::size_t>());
    if (!truth.at("noise").is_null()) continue;  // jittered drawings match in counts only
    REQUIRE(drawing.strokes.size() == svg.size());
    const bool shuffled = truth.at("svg_element_order") == "shuffled";
    const double start_x = truth.at("turtle").at("start_svg")[0];
    const double start_y = truth.at("turtle").at("start_svg")[1];
    double worst = 0;
    for (std::size_t k = 0; k < svg.size(); ++k) {
      const std::size_t index = shuffled ? truth.at("svg_element_derivation_index")[k].get<std::size_t>() : k;
      const std::vector<double> mine = stroke_numbers(drawing.strokes.at(index), start_x, start_y, svg[k].polyline);
      REQUIRE(mine.size() == svg[k].numbers.size());
      for (std::size_t i = 0; i < mine.size(); ++i) worst = std::max(worst, std::fabs(mine[i] - svg[k].numbers[i]));
    }
    INFO("largest coordinate difference " << worst);
    CHECK(worst <= 1e-3);
    ++compared;
  }
  CHECK(compared >= 1);
}
