#pragma once
// Arithmetic and logical expressions over named parameters: production conditions (`m>0`) and
// successor arguments (`8+0.25*m`). Parsed once into a small tree, evaluated per module.

#include "geometry/errors.h"

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace dg {

/// What an expression node is.
enum class ExpressionKind {
  Number,    ///< a literal (or the constant `pi`, then `name` is "pi")
  Variable,  ///< a named parameter
  Negate,    ///< unary minus of operands[0]
  Not,       ///< logical not of operands[0]
  Binary,    ///< `op` applied to operands[0] and operands[1]
  Call,      ///< function `name` applied to operands
};

/// Binary operators, from arithmetic to logic.
enum class BinaryOperator {
  Add, Subtract, Multiply, Divide, Power,
  Less, LessEqual, Greater, GreaterEqual, Equal, NotEqual,
  And, Or,
};

/// One node of an expression tree; children are owned by value.
struct Expression {
  ExpressionKind kind = ExpressionKind::Number;
  double number = 0;                        ///< Number: the value
  std::string name;                         ///< Variable / Call: the name; Number: "pi" or ""
  BinaryOperator op = BinaryOperator::Add;  ///< Binary: the operator
  std::vector<Expression> operands;         ///< Negate/Not: 1, Binary: 2, Call: the arguments

  friend bool operator==(const Expression&, const Expression&) = default;
};

/// A malformed expression. `column` is 1-based within the text given to parse_expression.
struct ExpressionSyntaxError : InputError {
  ExpressionSyntaxError(std::size_t column, std::string problem);
  std::size_t column;
  std::string problem;
};

/// Parses `text` (numbers like 2, 0.5, 1e-3; names; + - * / ^; unary - and !; comparisons
/// < <= > >= == !=; && ||; parentheses; functions sin cos tan atan2 sqrt abs min max floor ceil
/// exp log; the constant pi). `^` is right-associative and binds tighter than unary minus
/// (-2^2 = -4). Throws ExpressionSyntaxError on malformed text.
Expression parse_expression(std::string_view text);

/// A literal node holding `value`.
Expression number_expression(double value);

/// Names of the parameters the expression reads, sorted and without duplicates (`pi` excluded).
std::vector<std::string> expression_variables(const Expression& expression);

/// Evaluates with the binding names[i] = values[i]. Comparisons and logic give 1 or 0; angles of
/// the trigonometric functions are radians. Throws InputError for an unbound name.
double evaluate(const Expression& expression, std::span<const std::string> names, std::span<const double> values);

/// Compact text (`8+0.25*m`, minimal parentheses) that parse_expression reads back to the same tree.
std::string format_expression(const Expression& expression);

/// Shortest decimal text that reads back to exactly `value` (`336`, `0.993`, `1e-07`).
std::string format_number(double value);

}  // namespace dg
