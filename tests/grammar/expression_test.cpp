#include "grammar/expression.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace {

double eval(const std::string& text, const std::vector<std::string>& names = {}, const std::vector<double>& values = {}) {
  return dg::evaluate(dg::parse_expression(text), names, values);
}

}  // namespace

TEST_CASE("expressions follow the usual precedence", "[grammar]") {
  CHECK(eval("1+2*3") == 7);
  CHECK(eval("(1+2)*3") == 9);
  CHECK(eval("10-4-3") == 3);
  CHECK(eval("16/4/2") == 2);
  CHECK(eval("2^3^2") == 512);
  CHECK(eval("-2^2") == -4);
  CHECK(eval("2^-1") == 0.5);
  CHECK(eval("1e-3*1000") == Approx(1.0));
  CHECK(eval(".5+2.") == 2.5);
  CHECK(eval("1+2<4") == 1);
  CHECK(eval("3==3 && 2!=2") == 0);
  CHECK(eval("0 || 1 && 0") == 0);
  CHECK(eval("!0") == 1);
  CHECK(eval("!(2>1)") == 0);
  CHECK(eval("1 <= 1") == 1);
  CHECK(eval("2 >= 3") == 0);
}

TEST_CASE("expressions read bound parameters, functions and pi", "[grammar]") {
  CHECK(eval("8+0.25*m", {"m"}, {4}) == 9);
  CHECK(eval("m>0", {"m"}, {0}) == 0);
  CHECK(eval("m==0", {"m"}, {0}) == 1);
  CHECK(eval("max(a, b) - min(a, b)", {"a", "b"}, {3, 7}) == 4);
  CHECK(eval("sin(pi/2) + cos(0) + tan(0)") == Approx(2.0));
  CHECK(eval("atan2(1, 1)") == Approx(std::numbers::pi / 4));
  CHECK(eval("sqrt(16) + abs(-3) + floor(2.7) + ceil(2.1)") == 12);
  CHECK(eval("log(exp(2))") == Approx(2.0));
  CHECK(dg::expression_variables(dg::parse_expression("a*b+a-pi")) == std::vector<std::string>{"a", "b"});
  CHECK_THROWS_AS(eval("x+1"), dg::InputError);
}

TEST_CASE("expression syntax errors report a column", "[grammar]") {
  auto column_of = [](const std::string& text) {
    try {
      dg::parse_expression(text);
    } catch (const dg::ExpressionSyntaxError& error) {
      return error.column;
    }
    return std::size_t{0};
  };
  CHECK(column_of("1+") == 3);
  CHECK(column_of("(1+2") == 5);
  CHECK(column_of("1 $ 2") == 3);
  CHECK(column_of("foo(1)") == 1);
  CHECK(column_of("min(1)") == 1);
  CHECK(column_of("sin") == 1);
  CHECK(column_of("") == 1);
  CHECK(column_of("1e") == 3);
  CHECK(column_of("2 3") == 3);
  CHECK_THROWS_WITH(dg::parse_expression("m >"), Catch::Contains("column 4"));
}

TEST_CASE("formatted expressions read back to the same tree", "[grammar]") {
  for (const char* text : {"8+0.25*m", "m-1", "(a+b)*c", "a-(b-c)", "a/(b*c)", "-(a+b)", "2^3^2", "(2^3)^2",
                           "-2^2", "(-2)^2", "a- -2", "a*-b", "!(a&&b)||c", "a<b==(c>d)", "max(a,-b)+pi",
                           "1e-07*m", "0.993", "m>0 && m<=10"}) {
    const dg::Expression parsed = dg::parse_expression(text);
    const std::string printed = dg::format_expression(parsed);
    INFO(text << " -> " << printed);
    CHECK(dg::parse_expression(printed) == parsed);
  }
  CHECK(dg::format_expression(dg::parse_expression("8 + 0.25 * m")) == "8+0.25*m");
  CHECK(dg::format_expression(dg::parse_expression("(a*b)+c")) == "a*b+c");
  CHECK(dg::format_number(336) == "336");
  CHECK(dg::format_number(0.993) == "0.993");
}
