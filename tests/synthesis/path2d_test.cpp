#include "synthesis/path2d.h"

#include "geometry/errors.h"

#include <catch2/catch.hpp>

TEST_CASE("SVG path data parses absolute and relative commands", "[synthesis]") {
  const dg::Path2d path = dg::parse_svg_path("m1,2 10 0 v5 H0 c1 0 2 0 3 3 Z M-1-2L.5.5");
  REQUIRE(path.commands.size() == 8);
  CHECK(path.commands[1].points[0] == dg::Vec2(11, 2));   // implicit line-to after m
  CHECK(path.commands[2].points[0] == dg::Vec2(11, 7));
  CHECK(path.commands[3].points[0] == dg::Vec2(0, 7));
  CHECK(path.commands[4].points[2] == dg::Vec2(3, 10));
  CHECK(path.commands[5].type == dg::PathCommand::Type::Close);
  CHECK(path.commands[6].points[0] == dg::Vec2(-1, -2));
  CHECK(path.commands[7].points[0] == dg::Vec2(0.5, 0.5));
  CHECK(dg::format_svg_path(dg::parse_svg_path("M 0 0 C 3 6 11 7 16 0 Z"), 3) == "M 0 0 C 3 6 11 7 16 0 Z");
  CHECK(dg::format_svg_number(141.74579, 3) == "141.746");
  CHECK(dg::format_svg_number(-0.0001, 3) == "0");
}

TEST_CASE("malformed path data is an input error", "[synthesis]") {
  CHECK_THROWS_AS(dg::parse_svg_path(""), dg::InputError);
  CHECK_THROWS_AS(dg::parse_svg_path("L 1 1"), dg::InputError);
  CHECK_THROWS_AS(dg::parse_svg_path("M 1"), dg::InputError);
  CHECK_THROWS_WITH(dg::parse_svg_path("M 0 0 A 1 1 0 0 0 2 2"), Catch::Contains("unsupported command 'A'"));
}

TEST_CASE("flattening splits curves and closes subpaths", "[synthesis]") {
  const dg::Path2d path = dg::parse_svg_path("M 0 0 C 0 10 10 10 10 0 Z");
  const auto lines = dg::flatten_path(path, 1.0);
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].size() > 20);
  CHECK(lines[0].back() == dg::Vec2(0, 0));
  const dg::Vec2 middle = lines[0][(lines[0].size() - 2) / 2];
  CHECK(middle.y() == Approx(7.5).margin(0.3));
}
