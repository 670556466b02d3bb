#include "grammar/lsystem_json.h"

#include "grammar/lsystem_text.h"

#include <catch2/catch.hpp>

#include <string>

namespace {

using Json = nlohmann::ordered_json;

std::string error_of(const Json& json) {
  try {
    dg::lsystem_from_json(json, "case.json");
  } catch (const dg::InputError& error) {
    return error.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("the JSON form reads the corpus lsystem field", "[grammar]") {
  const Json json = Json::parse(R"J({"axiom": "P(336)",
    "rules": {"P(m) : m>0": "A f(27.5) *(0.993) +(8.5) P(m-1)", "P(m) : m==0": ""},
    "iterations": 337, "angle": 8.5, "scale": 0.993, "scale_ratio": 1.007049, "step": null})J");
  const dg::LSystem system = dg::lsystem_from_json(json, "helix.json");
  CHECK(system == dg::parse_lsystem_text("axiom: P(336)\niterations: 337\nangle: 8.5\nscale: 0.993\n"
                                         "P(m) : m>0 -> A f(27.5) *(0.993) +(8.5) P(m-1)\nP(m) : m==0 -> ε\n",
                                         "helix.ls"));
}

TEST_CASE("JSON stochastic alternatives and turtle extras round trip", "[grammar]") {
  const dg::LSystem system = dg::parse_lsystem_text(
      "axiom: F\nangle: 25\nstep: 3\nheading: 90\ndraw: F G\nmotif A: M 0 0 L 1 0\n"
      "F -> (0.3) F[+F]F\nF -> (0.7) F[-F]F\nG : 1 -> (2) ε\nP(m) : m>0 -> A f(m) P(m-1)\n",
      "s.ls");
  const Json json = dg::lsystem_to_json(system);
  REQUIRE(json["rules"]["F"].is_array());
  CHECK(json["rules"]["F"][0] == "(0.3) F[+F]F");
  CHECK(json["rules"]["G : 1"] == "(2)");
  CHECK(json["scale"].is_null());
  CHECK(json["draw"] == Json::array({"F", "G"}));
  CHECK(dg::lsystem_from_json(Json::parse(json.dump()), "again.json") == system);
}

TEST_CASE("a whole corpus case also fills drawing symbols, motifs and heading", "[grammar]") {
  const Json json = Json::parse(R"J({"id": "x", "lsystem": {"axiom": "L", "rules": {"L": "L+R+"}, "angle": 90, "step": 10},
    "symbols": {"L": "draw one segment", "R": "draw one segment", "A": "place one copy of motif \"flag\"", "+": "turn left"},
    "motif": {"local_path": "M 0 0 L 9.6 0"}, "turtle": {"start_heading_deg": 90}})J");
  const dg::LSystem system = dg::lsystem_from_json(json, "case.json");
  CHECK(system.turtle.draw_symbols == std::vector<std::string>{"L", "R"});
  CHECK(system.turtle.motifs.at("A") == "M 0 0 L 9.6 0");
  CHECK(system.turtle.heading_deg == 90);
}

TEST_CASE("JSON errors name the file and the rule", "[grammar]") {
  CHECK(error_of(Json::array()) == "case.json: expected a JSON object with \"axiom\" and \"rules\"");
  CHECK(error_of({{"rules", Json::object()}}) == "case.json: missing \"axiom\"");
  CHECK(error_of({{"axiom", "F"}, {"rules", {{"F", "F[+F(]"}}}}) ==
        "case.json: rule \"F\": successor \"F[+F(]\": column 5: '(' is never closed");
  CHECK(error_of({{"axiom", "F"}, {"rules", {{"P(m) : k>0", "A"}}}}) ==
        "case.json: rule \"P(m) : k>0\": column 8: 'k' is not a parameter of P(m)");
  CHECK(error_of({{"axiom", "F"}, {"angle", "90"}}) == "case.json: \"angle\" must be a number");
  CHECK(error_of({{"axiom", "F"}, {"rules", {{"F", Json::array()}}}}) ==
        "case.json: rule \"F\": the list of alternatives is empty");
  CHECK(error_of({{"axiom", 3}}) == "case.json: \"axiom\" must be a string");
}
