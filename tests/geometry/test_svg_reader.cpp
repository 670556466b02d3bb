// SVG input: path commands, shapes, transforms, XML details and malformed input.

#include "geometry/errors.h"
#include "geometry/svg_reader.h"

#include <catch2/catch.hpp>

#include <string>

using namespace dg;

namespace {

SvgDrawing svg(const std::string& body, const std::string& root_attributes = "") {
  return parse_svg("<svg xmlns=\"http://www.w3.org/2000/svg\"" + root_attributes + ">\n" + body + "\n</svg>\n", "test.svg");
}

bool near(const Vec2& a, double x, double y, double tolerance = 1e-9) { return (a - Vec2(x, y)).norm() <= tolerance; }

std::string error_of(const std::string& text) {
  try {
    parse_svg(text, "bad.svg");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("svg: straight path commands, absolute and relative", "[geometry][svg]") {
  const SvgDrawing d = svg("<path d=\"M 1 2 L 3 4 H 10 V 0 l 1 1 h -2 v 3 m 5 5 l 1,0 2-1Z\"/>");
  REQUIRE(d.elements.size() == 1);
  const auto& p = d.elements[0].polylines;
  REQUIRE(p.size() == 2);
  REQUIRE(p[0].size() == 7);
  CHECK(near(p[0][1], 3, 4));
  CHECK(near(p[0][2], 10, 4));
  CHECK(near(p[0][3], 10, 0));
  CHECK(near(p[0][4], 11, 1));
  CHECK(near(p[0][5], 9, 1));
  CHECK(near(p[0][6], 9, 4));
  // m 5 5 from (9,4) -> (14,9); implicit relative line-tos; Z closes back to (14,9)
  REQUIRE(p[1].size() == 4);
  CHECK(near(p[1][0], 14, 9));
  CHECK(near(p[1][1], 15, 9));
  CHECK(near(p[1][2], 17, 8));
  CHECK(near(p[1][3], 14, 9));
  CHECK(d.elements[0].tag == "path");
  CHECK(d.elements[0].line == 2);
}

TEST_CASE("svg: implicit line-tos after M and compact numbers", "[geometry][svg]") {
  const auto p = flatten_svg_path_data("M0,0 1.5.5-2e1-1");
  REQUIRE(p.size() == 1);
  REQUIRE(p[0].size() == 3);
  CHECK(near(p[0][1], 1.5, 0.5));
  CHECK(near(p[0][2], -20, -1));
}

TEST_CASE("svg: cubic and quadratic curves with reflections", "[geometry][svg]") {
  // C and c end at their end points; S reflects the previous control point.
  auto p = flatten_svg_path_data("M 0 0 C 0 10 10 10 10 0 S 20 -10 20 0 c 1 1 2 1 3 0");
  REQUIRE(p.size() == 1);
  CHECK(near(p[0].back(), 23, 0));
  // The S piece mirrors (10,10) about (10,0): its midpoint is (15, -7.5) by symmetry of the curve.
  bool found_mid = false;
  for (const Vec2& q : p[0]) found_mid |= near(q, 15, -7.5, 1e-6);
  CHECK(found_mid);
  // Q and T: T reflects the Q control point; q/t relative
  p = flatten_svg_path_data("M 0 0 Q 5 10 10 0 T 20 0 q 5 5 10 0 t 10 0");
  CHECK(near(p[0].back(), 40, 0));
  double low = 0;  // T's curve mirrors Q's bump: its lowest point is (15, -5)
  for (const Vec2& q : p[0])
    if (q.x() > 10 && q.x() < 20) low = std::min(low, q.y());
  CHECK(low == Approx(-5).margin(0.01));
}

TEST_CASE("svg: elliptical arcs", "[geometry][svg]") {
  // Half circle of radius 5 from (0,0) to (10,0) through (5,-5) (sweep=1: positive angle in y-down).
  auto p = flatten_svg_path_data("M 0 0 A 5 5 0 0 1 10 0");
  REQUIRE(p.size() == 1);
  CHECK(near(p[0].back(), 10, 0));
  double min_y = 0;
  for (const Vec2& q : p[0]) {
    CHECK(std::abs((q - Vec2(5, 0)).norm() - 5) < 1e-9);
    min_y = std::min(min_y, q.y());
  }
  CHECK(min_y == Approx(-5).margin(0.05));
  // Relative arc with compact flags and a too-small radius (scaled up to reach the end).
  p = flatten_svg_path_data("M 0 0 a1 1 0 00 10 0");
  CHECK(near(p[0].back(), 10, 0));
  double max_y = 0;
  for (const Vec2& q : p[0]) max_y = std::max(max_y, q.y());
  CHECK(max_y == Approx(5).margin(0.05));
}

TEST_CASE("svg: basic shapes", "[geometry][svg]") {
  const SvgDrawing d = svg(
      "<line x1=\"1\" y1=\"2\" x2=\"3\" y2=\"4\"/>\n"
      "<polyline points=\"0,0 1,0 1,1\"/>\n"
      "<polygon points=\"0 0 2 0 2 2\"/>\n"
      "<rect x=\"1\" y=\"1\" width=\"4\" height=\"2\"/>\n"
      "<circle cx=\"5\" cy=\"5\" r=\"2\"/>\n"
      "<ellipse cx=\"0\" cy=\"0\" rx=\"3\" ry=\"1\"/>\n"
      "<rect x=\"0\" y=\"0\" width=\"10\" height=\"10\" rx=\"2\"/>");
  REQUIRE(d.elements.size() == 7);
  CHECK(d.elements[0].polylines[0].size() == 2);
  CHECK(near(d.elements[0].polylines[0][1], 3, 4));
  CHECK(d.elements[1].polylines[0].size() == 3);
  const auto& polygon = d.elements[2].polylines[0];
  CHECK(polygon.size() == 4);
  CHECK(near(polygon.back(), 0, 0));
  const auto& rect = d.elements[3].polylines[0];
  CHECK(rect.size() == 5);
  CHECK(near(rect[0], 1, 1));
  CHECK(near(rect[2], 5, 3));
  for (const Vec2& q : d.elements[4].polylines[0]) CHECK(std::abs((q - Vec2(5, 5)).norm() - 2) < 1e-9);
  for (const Vec2& q : d.elements[5].polylines[0]) CHECK(q.x() * q.x() / 9 + q.y() * q.y() == Approx(1));
  for (const Vec2& q : d.elements[6].polylines[0]) {  // rounded corners stay inside the box
    CHECK(q.x() >= -1e-9);
    CHECK(q.x() <= 10 + 1e-9);
  }
  CHECK(d.elements[6].polylines[0].size() > 8);
}

TEST_CASE("svg: nested groups with transforms", "[geometry][svg]") {
  const SvgDrawing d = svg(
      "<g transform=\"translate(10,20)\">\n"
      "  <g transform=\"scale(2) rotate(90)\">\n"
      "    <line x1=\"0\" y1=\"0\" x2=\"1\" y2=\"0\"/>\n"
      "  </g>\n"
      "  <line x1=\"0\" y1=\"0\" x2=\"1\" y2=\"0\" transform=\"matrix(1 0 0 1 5 5)\"/>\n"
      "</g>\n"
      "<line x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\" transform=\"skewX(45)\"/>\n"
      "<line x1=\"1\" y1=\"0\" x2=\"0\" y2=\"0\" transform=\"skewY(45) rotate(180 1 0)\"/>",
      " viewBox=\"0 0 100 50\" width=\"200\" height=\"100\"");
  CHECK(d.width == 100);
  CHECK(d.height == 50);
  REQUIRE(d.elements.size() == 4);
  // translate(10,20) scale(2) rotate(90): (1,0) -> rotate -> (0,1) -> scale -> (0,2) -> (10,22)
  CHECK(near(d.elements[0].polylines[0][0], 10, 20));
  CHECK(near(d.elements[0].polylines[0][1], 10, 22));
  CHECK(near(d.elements[1].polylines[0][0], 15, 25));
  CHECK(near(d.elements[2].polylines[0][0], 1, 1));  // skewX(45): x += y
  // rotate(180 about (1,0)) maps (1,0)->(1,0), (0,0)->(2,0); skewY(45): y += x
  CHECK(near(d.elements[3].polylines[0][0], 1, 1));
  CHECK(near(d.elements[3].polylines[0][1], 2, 2));
}

TEST_CASE("svg: XML details (comments, CDATA, entities, declarations, hidden containers)", "[geometry][svg]") {
  const std::string text =
      "\xEF\xBB\xBF<?xml version=\"1.0\"?>\n"
      "<!DOCTYPE svg [ <!ENTITY x \"y\"> ]>\n"
      "<!-- <path d=\"M 0 0 L 9 9\"/> -->\n"
      "<svg width=\"10px\" height='20'>\n"
      "<style><![CDATA[ path { stroke: red } <path/> ]]></style>\n"
      "<defs><path d=\"M 0 0 L 1 1\"/></defs>\n"
      "<title>a &amp; b</title>\n"
      "<polyline points=\"0&#44;0 &#x31;,1\"/>\n"
      "<text x=\"1\">hi</text>\n"
      "</svg>\n";
  const SvgDrawing d = parse_svg(text, "x.svg");
  CHECK(d.width == 10);
  CHECK(d.height == 20);
  REQUIRE(d.elements.size() == 1);
  CHECK(d.elements[0].line == 8);
  CHECK(near(d.elements[0].polylines[0][1], 1, 1));
}

TEST_CASE("svg: malformed input names file and line", "[geometry][svg]") {
  CHECK(error_of("<svg>\n<path d=\"M 0 0 L\"/>\n</svg>") == "bad.svg:2: path data: missing number after 'L'");
  CHECK(error_of("<svg>\n<path d=\"L 0 0\"/>\n</svg>") == "bad.svg:2: path data: does not start with M");
  CHECK(error_of("<svg>\n\n<path d=\"M 0 0 X 1 1\"/>\n</svg>") == "bad.svg:3: path data: unknown command 'X'");
  CHECK(error_of("<svg>\n<g>\n</svg>") == "bad.svg:3: end tag </svg> does not match <g> of line 2");
  CHECK(error_of("<svg>\n<g>\n") == "bad.svg:2: <g> is never closed");
  CHECK(error_of("<svg>\n<line x1=\"a\"/>\n</svg>") == "bad.svg:2: attribute x1=\"a\" is not a number");
  CHECK(error_of("<svg>\n<line x1=1/>\n</svg>") == "bad.svg:2: value of 'x1' is not quoted");
  CHECK(error_of("<svg>\n<g transform=\"spin(3)\"/>\n</svg>") == "bad.svg:2: transform: unknown transform 'spin'");
  CHECK(error_of("<svg>\n<g transform=\"rotate(1 2)\"/>\n</svg>") == "bad.svg:2: transform: rotate has 2 numbers");
  CHECK(error_of("<svg>\n<polyline points=\"0 0 1\"/>\n</svg>") == "bad.svg:2: <polyline> has an odd number of coordinates");
  CHECK(error_of("<svg>\n<!-- open\n</svg>") == "bad.svg:2: comment is not closed");
  CHECK(error_of("<html></html>") == "bad.svg:1: root element is <html>, not <svg>");
  CHECK(error_of("") == "bad.svg:1: no <svg> element");
  CHECK(error_of("<svg>\n<path d=\"M 0 0 A 1 1 0 2 0 1 1\"/>\n</svg>") == "bad.svg:2: path data: arc flags must be 0 or 1");
  CHECK(error_of("<svg>\n<title>&bogus;</title>\n</svg>").empty());  // text content is not decoded
  CHECK(error_of("<svg>\n<g id=\"&bogus;\"/>\n</svg>") == "bad.svg:2: unknown entity &bogus;");
  CHECK(error_of("<svg>\n</g>\n</svg>") == "bad.svg:2: end tag </g> does not match <svg> of line 1");
  CHECK(error_of("<svg><line x1=\"1e999\"/></svg>") == "bad.svg:1: number out of range: 1e999");
  CHECK_THROWS_AS(read_svg("/nonexistent/file.svg"), InputError);
}

TEST_CASE("svg: corpus file reads one element per line", "[geometry][svg]") {
  const std::string path = DOCKGRAMMAR_SOURCE_DIR "/../shared/corpus/lsystems/stava_helix_336.svg";
  SvgDrawing d;
  try {
    d = read_svg(path);
  } catch (const InputError&) {
    WARN("corpus absent: " << path);
    return;
  }
  CHECK(d.elements.size() == 336);
  CHECK(d.width == 353);
  CHECK(near(d.elements[0].polylines[0][0], 141.746, 360.18));
  CHECK(d.elements[0].polylines[0].size() > 10);
}

TEST_CASE("svg: use references elements in defs and symbols", "[geometry][svg]") {
  const SvgDrawing d = svg(
      "<defs><path id=\"seg\" d=\"M 0 0 L 1 0\"/></defs>\n"
      "<symbol id=\"sym\"><line x1=\"0\" y1=\"0\" x2=\"0\" y2=\"2\"/></symbol>\n"
      "<use href=\"#seg\" x=\"10\" y=\"5\"/>\n"
      "<g transform=\"scale(2)\"><use xlink:href=\"#seg\" transform=\"translate(1 1)\"/></g>\n"
      "<use href=\"#sym\" x=\"3\"/>");
  REQUIRE(d.elements.size() == 3);
  CHECK(near(d.elements[0].polylines[0][0], 10, 5));
  CHECK(near(d.elements[0].polylines[0][1], 11, 5));
  CHECK(near(d.elements[1].polylines[0][0], 2, 2));
  CHECK(near(d.elements[1].polylines[0][1], 4, 2));
  CHECK(near(d.elements[2].polylines[0][1], 3, 2));
  CHECK(error_of("<svg>\n<use href=\"#nope\"/>\n</svg>") == "bad.svg:2: <use> refers to the unknown id \"nope\"");
  CHECK(error_of("<svg>\n<g id=\"a\"><use href=\"#a\"/></g>\n</svg>") == "bad.svg:2: <use> references nest too deep (a cycle?)");
}
