#include "grammar/expression.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <utility>

namespace dg {

namespace {

struct FunctionInfo {
  std::string_view name;
  std::size_t arity;
};

constexpr std::array<FunctionInfo, 12> functions{{{"sin", 1}, {"cos", 1}, {"tan", 1}, {"atan2", 2}, {"sqrt", 1},
                                                  {"abs", 1}, {"min", 2}, {"max", 2}, {"floor", 1}, {"ceil", 1},
                                                  {"exp", 1}, {"log", 1}}};

const FunctionInfo* find_function(std::string_view name) {
  for (const FunctionInfo& f : functions)
    if (f.name == name) return &f;
  return nullptr;
}

Expression binary(BinaryOperator op, Expression left, Expression right) {
  Expression e;
  e.kind = ExpressionKind::Binary;
  e.op = op;
  e.operands.push_back(std::move(left));
  e.operands.push_back(std::move(right));
  return e;
}

Expression unary(ExpressionKind kind, Expression operand) {
  Expression e;
  e.kind = kind;
  e.operands.push_back(std::move(operand));
  return e;
}

bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Recursive-descent parser; one method per precedence level, lowest first.
class Parser {
 public:
  explicit Parser(std::string_view text) : text_(text) {}

  Expression parse_all() {
    skip_space();
    if (pos_ == text_.size()) fail("empty expression");
    Expression e = parse_or();
    skip_space();
    if (pos_ != text_.size()) fail("unexpected '" + std::string(1, text_[pos_]) + "'");
    return e;
  }

 private:
  [[noreturn]] void fail(std::string problem) const { throw ExpressionSyntaxError(pos_ + 1, std::move(problem)); }

  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }

  // Consumes `token` when it comes next (after spaces).
  bool accept(std::string_view token) {
    skip_space();
    if (text_.substr(pos_, token.size()) != token) return false;
    pos_ += token.size();
    return true;
  }

  Expression parse_or() {
    Expression e = parse_and();
    while (accept("||")) e = binary(BinaryOperator::Or, std::move(e), parse_and());
    return e;
  }

  Expression parse_and() {
    Expression e = parse_equality();
    while (accept("&&")) e = binary(BinaryOperator::And, std::move(e), parse_equality());
    return e;
  }

  Expression parse_equality() {
    Expression e = parse_relational();
    for (;;) {
      if (accept("=="))
        e = binary(BinaryOperator::Equal, std::move(e), parse_relational());
      else if (accept("!="))
        e = binary(BinaryOperator::NotEqual, std::move(e), parse_relational());
      else
        return e;
    }
  }

  Expression parse_relational() {
    Expression e = parse_additive();
    for (;;) {
      if (accept("<="))
        e = binary(BinaryOperator::LessEqual, std::move(e), parse_additive());
      else if (accept(">="))
        e = binary(BinaryOperator::GreaterEqual, std::move(e), parse_additive());
      else if (accept("<"))
        e = binary(BinaryOperator::Less, std::move(e), parse_additive());
      else if (accept(">"))
        e = binary(BinaryOperator::Greater, std::move(e), parse_additive());
      else
        return e;
    }
  }

  Expression parse_additive() {
    Expression e = parse_multiplicative();
    for (;;) {
      if (accept("+"))
        e = binary(BinaryOperator::Add, std::move(e), parse_multiplicative());
      else if (accept("-"))
        e = binary(BinaryOperator::Subtract, std::move(e), parse_multiplicative());
      else
        return e;
    }
  }

  Expression parse_multiplicative() {
    Expression e = parse_unary();
    for (;;) {
      if (accept("*"))
        e = binary(BinaryOperator::Multiply, std::move(e), parse_unary());
      else if (accept("/"))
        e = binary(BinaryOperator::Divide, std::move(e), parse_unary());
      else
        return e;
    }
  }

  // Unary minus of a plain literal folds into a negative literal, so `-2` is a number.
  Expression parse_unary() {
    if (accept("-")) {
      Expression operand = parse_unary();
      if (operand.kind == ExpressionKind::Number && operand.name.empty() && operand.number > 0)
        return number_expression(-operand.number);
      return unary(ExpressionKind::Negate, std::move(operand));
    }
    skip_space();
    if (text_.substr(pos_, 2) != "!=" && accept("!")) return unary(ExpressionKind::Not, parse_unary());
    return parse_power();
  }

  Expression parse_power() {
    Expression base = parse_primary();
    if (accept("^")) return binary(BinaryOperator::Power, std::move(base), parse_unary());
    return base;
  }

  Expression parse_primary() {
    skip_space();
    if (pos_ == text_.size()) fail("expression ends where a value is expected");
    const char c = text_[pos_];
    if (c == '(') {
      ++pos_;
      Expression e = parse_or();
      if (!accept(")")) fail("missing ')'");
      return e;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return parse_number();
    if (is_name_start(c)) return parse_name();
    fail("unexpected '" + std::string(1, c) + "'");
  }

  Expression parse_number() {
    const std::size_t start = pos_;
    auto digits = [&] {
      std::size_t n = 0;
      while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_, ++n;
      return n;
    };
    std::size_t mantissa = digits();
    if (pos_ < text_.size() && text_[pos_] == '.') {
      ++pos_;
      mantissa += digits();
    }
    if (mantissa == 0) fail("malformed number");
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      ++pos_;
      if (pos_ < text_.size() && (text_[pos_] == '+' || text_[pos_] == '-')) ++pos_;
      if (digits() == 0) fail("malformed exponent");
    }
    double value = 0;
    const auto [end, error] = std::from_chars(text_.data() + start, text_.data() + pos_, value);
    if (error != std::errc() || end != text_.data() + pos_ || !std::isfinite(value)) {
      pos_ = start;
      fail("number out of range");
    }
    return number_expression(value);
  }

  Expression parse_name() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && is_name_char(text_[pos_])) ++pos_;
    std::string name(text_.substr(start, pos_ - start));
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == '(') {
      const FunctionInfo* function = find_function(name);
      if (!function) {
        pos_ = start;
        fail("unknown function '" + name + "'");
      }
      ++pos_;
      Expression call;
      call.kind = ExpressionKind::Call;
      call.name = name;
      if (!accept(")")) {
        do call.operands.push_back(parse_or());
        while (accept(","));
        if (!accept(")")) fail("missing ')' after the arguments of " + name);
      }
      if (call.operands.size() != function->arity) {
        pos_ = start;
        fail(name + " takes " + std::to_string(function->arity) + " argument(s), got " +
             std::to_string(call.operands.size()));
      }
      return call;
    }
    if (find_function(name)) {
      pos_ = start;
      fail("function '" + name + "' needs arguments in parentheses");
    }
    if (name == "pi") {
      Expression e = number_expression(std::numbers::pi);
      e.name = "pi";
      return e;
    }
    Expression e;
    e.kind = ExpressionKind::Variable;
    e.name = std::move(name);
    return e;
  }

  std::string_view text_;
  std::size_t pos_ = 0;
};

void collect_variables(const Expression& e, std::vector<std::string>& out) {
  if (e.kind == ExpressionKind::Variable) out.push_back(e.name);
  for (const Expression& operand : e.operands) collect_variables(operand, out);
}

double call_function(const std::string& name, const double* a) {
  if (name == "sin") return std::sin(a[0]);
  if (name == "cos") return std::cos(a[0]);
  if (name == "tan") return std::tan(a[0]);
  if (name == "atan2") return std::atan2(a[0], a[1]);
  if (name == "sqrt") return std::sqrt(a[0]);
  if (name == "abs") return std::fabs(a[0]);
  if (name == "min") return std::min(a[0], a[1]);
  if (name == "max") return std::max(a[0], a[1]);
  if (name == "floor") return std::floor(a[0]);
  if (name == "ceil") return std::ceil(a[0]);
  if (name == "exp") return std::exp(a[0]);
  return std::log(a[0]);  // the parser admits no other name
}

// Binding strength used for printing: higher binds tighter.
int precedence(const Expression& e) {
  switch (e.kind) {
    case ExpressionKind::Number: return e.number < 0 && e.name.empty() ? 7 : 9;
    case ExpressionKind::Variable:
    case ExpressionKind::Call: return 9;
    case ExpressionKind::Negate:
    case ExpressionKind::Not: return 7;
    case ExpressionKind::Binary: break;
  }
  switch (e.op) {
    case BinaryOperator::Or: return 1;
    case BinaryOperator::And: return 2;
    case BinaryOperator::Equal:
    case BinaryOperator::NotEqual: return 3;
    case BinaryOperator::Less:
    case BinaryOperator::LessEqual:
    case BinaryOperator::Greater:
    case BinaryOperator::GreaterEqual: return 4;
    case BinaryOperator::Add:
    case BinaryOperator::Subtract: return 5;
    case BinaryOperator::Multiply:
    case BinaryOperator::Divide: return 6;
    case BinaryOperator::Power: return 8;
  }
  return 9;
}

std::string_view operator_text(BinaryOperator op) {
  switch (op) {
    case BinaryOperator::Add: return "+";
    case BinaryOperator::Subtract: return "-";
    case BinaryOperator::Multiply: return "*";
    case BinaryOperator::Divide: return "/";
    case BinaryOperator::Power: return "^";
    case BinaryOperator::Less: return "<";
    case BinaryOperator::LessEqual: return "<=";
    case BinaryOperator::Greater: return ">";
    case BinaryOperator::GreaterEqual: return ">=";
    case BinaryOperator::Equal: return "==";
    case BinaryOperator::NotEqual: return "!=";
    case BinaryOperator::And: return "&&";
    case BinaryOperator::Or: return "||";
  }
  return "?";
}

std::string parenthesized_if(bool wrap, std::string text) {
  if (!wrap) return text;
  std::string wrapped = "(";
  wrapped += text;
  wrapped += ')';
  return wrapped;
}

}  // namespace

ExpressionSyntaxError::ExpressionSyntaxError(std::size_t column_, std::string problem_)
    : InputError("column " + std::to_string(column_) + ": " + problem_), column(column_), problem(std::move(problem_)) {}

Expression parse_expression(std::string_view text) { return Parser(text).parse_all(); }

Expression number_expression(double value) {
  Expression e;
  e.number = value;
  return e;
}

std::vector<std::string> expression_variables(const Expression& expression) {
  std::vector<std::string> names;
  collect_variables(expression, names);
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

double evaluate(const Expression& e, std::span<const std::string> names, std::span<const double> values) {
  switch (e.kind) {
    case ExpressionKind::Number: return e.number;
    case ExpressionKind::Variable:
      for (std::size_t i = 0; i < names.size() && i < values.size(); ++i)
        if (names[i] == e.name) return values[i];
      throw InputError("unknown parameter '" + e.name + "'");
    case ExpressionKind::Negate: return -evaluate(e.operands[0], names, values);
    case ExpressionKind::Not: return evaluate(e.operands[0], names, values) == 0 ? 1 : 0;
    case ExpressionKind::Call: {
      std::array<double, 2> args{};
      for (std::size_t i = 0; i < e.operands.size() && i < args.size(); ++i)
        args[i] = evaluate(e.operands[i], names, values);
      return call_function(e.name, args.data());
    }
    case ExpressionKind::Binary: break;
  }
  const double a = evaluate(e.operands[0], names, values);
  if (e.op == BinaryOperator::And) return a != 0 && evaluate(e.operands[1], names, values) != 0 ? 1 : 0;
  if (e.op == BinaryOperator::Or) return a != 0 || evaluate(e.operands[1], names, values) != 0 ? 1 : 0;
  const double b = evaluate(e.operands[1], names, values);
  switch (e.op) {
    case BinaryOperator::Add: return a + b;
    case BinaryOperator::Subtract: return a - b;
    case BinaryOperator::Multiply: return a * b;
    case BinaryOperator::Divide: return a / b;
    case BinaryOperator::Power: return std::pow(a, b);
    case BinaryOperator::Less: return a < b ? 1 : 0;
    case BinaryOperator::LessEqual: return a <= b ? 1 : 0;
    case BinaryOperator::Greater: return a > b ? 1 : 0;
    case BinaryOperator::GreaterEqual: return a >= b ? 1 : 0;
    case BinaryOperator::Equal: return a == b ? 1 : 0;
    case BinaryOperator::NotEqual: return a != b ? 1 : 0;
    case BinaryOperator::And:
    case BinaryOperator::Or: break;
  }
  return 0;
}

std::string format_expression(const Expression& e) {
  switch (e.kind) {
    case ExpressionKind::Number: return e.name.empty() ? format_number(e.number) : e.name;
    case ExpressionKind::Variable: return e.name;
    case ExpressionKind::Negate:
    case ExpressionKind::Not:
      return (e.kind == ExpressionKind::Negate ? "-" : "!") +
             parenthesized_if(precedence(e.operands[0]) < 7, format_expression(e.operands[0]));
    case ExpressionKind::Call: {
      std::string text = e.name + "(";
      for (std::size_t i = 0; i < e.operands.size(); ++i)
      {
        if (i) text += ',';
        text += format_expression(e.operands[i]);
      }
      return text + ")";
    }
    case ExpressionKind::Binary: break;
  }
  const int p = precedence(e);
  const int left = precedence(e.operands[0]);
  const int right = precedence(e.operands[1]);
  // Power is right-associative with a unary right operand; the others are left-associative.
  const bool wrap_left = e.op == BinaryOperator::Power ? left < 9 : left < p;
  const bool wrap_right = e.op == BinaryOperator::Power ? right < 7 : right <= p;
  std::string right_text = format_expression(e.operands[1]);
  // Keep `a- -2` apart so the two minus signs do not read as one token pair like `--`.
  const std::string_view op = operator_text(e.op);
  const bool space = !wrap_right && !right_text.empty() && (right_text[0] == '-' || right_text[0] == '!');
  return parenthesized_if(wrap_left, format_expression(e.operands[0])) + std::string(op) + (space ? " " : "") +
         parenthesized_if(wrap_right, std::move(right_text));
}

std::string format_number(double value) {
  if (value == 0) return "0";  // also for -0
  std::array<char, 64> buffer{};
  const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return error == std::errc() ? std::string(buffer.data(), end) : std::string("0");
}

}  // namespace dg
