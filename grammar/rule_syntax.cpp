#include "grammar/rule_syntax.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace dg {

namespace {

constexpr std::string_view epsilon = "\xCE\xB5";  // ε in UTF-8

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

std::size_t skip_space(std::string_view text, std::size_t pos) {
  while (pos < text.size() && is_space(text[pos])) ++pos;
  return pos;
}

std::string_view trim(std::string_view text) {
  std::size_t begin = skip_space(text, 0);
  std::size_t end = text.size();
  while (end > begin && is_space(text[end - 1])) --end;
  return text.substr(begin, end - begin);
}

[[noreturn]] void fail(std::size_t pos, std::string problem) { throw ExpressionSyntaxError(pos + 1, std::move(problem)); }

// Index of the ')' that closes the '(' at `open`; commas at depth one are appended to `commas`.
std::size_t closing_parenthesis(std::string_view text, std::size_t open, std::vector<std::size_t>& commas) {
  int depth = 0;
  for (std::size_t i = open; i < text.size(); ++i) {
    if (text[i] == '(') ++depth;
    if (text[i] == ')' && --depth == 0) return i;
    if (text[i] == ',' && depth == 1) commas.push_back(i);
  }
  fail(open, "'(' is never closed");
}

Expression parse_piece(std::string_view text, std::size_t begin, std::size_t end) {
  try {
    return parse_expression(text.substr(begin, end - begin));
  } catch (const ExpressionSyntaxError& error) {
    throw shift_column(error, begin);
  }
}

// Names an expression reads that are not among `formals`.
void check_names(const Expression& expression, const Production& production, std::size_t column) {
  for (const std::string& name : expression_variables(expression))
    if (std::find(production.formals.begin(), production.formals.end(), name) == production.formals.end())
      fail(column, "'" + name + "' is not a parameter of " + format_left_side(Production{production.predecessor,
                                                                                          production.formals, {}, {}, 1}));
}

bool is_identifier(std::string_view name) {
  if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_')) return false;
  return std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// Successor items with the start column (0-based) of each item's arguments.
std::vector<SuccessorItem> parse_items(std::string_view text, std::vector<std::size_t>* argument_columns) {
  std::vector<SuccessorItem> items;
  if (trim(text).empty() || trim(text) == epsilon) return items;
  std::size_t pos = skip_space(text, 0);
  while (pos < text.size()) {
    const std::size_t length = symbol_length(text, pos);
    if (length == 0) {
      if (text.substr(pos, epsilon.size()) == epsilon) fail(pos, "'ε' must stand alone (it is the empty successor)");
      fail(pos, "unexpected '" + std::string(1, text[pos]) + "' where a symbol is expected");
    }
    SuccessorItem item;
    item.symbol = std::string(text.substr(pos, length));
    pos += length;
    if (argument_columns) argument_columns->push_back(pos);
    if (pos < text.size() && text[pos] == '(') {
      std::vector<std::size_t> commas;
      const std::size_t close = closing_parenthesis(text, pos, commas);
      std::size_t begin = pos + 1;
      for (std::size_t comma : commas) {
        item.arguments.push_back(parse_piece(text, begin, comma));
        begin = comma + 1;
      }
      item.arguments.push_back(parse_piece(text, begin, close));
      pos = close + 1;
    }
    items.push_back(std::move(item));
    pos = skip_space(text, pos);
  }
  return items;
}

}  // namespace

ExpressionSyntaxError shift_column(const ExpressionSyntaxError& error, std::size_t offset) {
  return ExpressionSyntaxError(error.column + offset, error.problem);
}

std::vector<SuccessorItem> parse_successor(std::string_view text) { return parse_items(text, nullptr); }

std::vector<Module> parse_axiom(std::string_view text) {
  std::vector<std::size_t> columns;
  std::vector<SuccessorItem> items = parse_items(text, &columns);
  if (items.empty()) fail(0, "the axiom is empty");
  std::vector<Module> axiom;
  for (std::size_t i = 0; i < items.size(); ++i) {
    Module module{items[i].symbol, {}};
    for (const Expression& argument : items[i].arguments) {
      const std::vector<std::string> names = expression_variables(argument);
      if (!names.empty()) fail(columns[i] + 1, "the axiom cannot use the name '" + names.front() + "'");
      const double value = evaluate(argument, {}, {});
      if (!std::isfinite(value)) fail(columns[i] + 1, "argument of " + module.symbol + " is not finite");
      module.parameters.push_back(value);
    }
    axiom.push_back(std::move(module));
  }
  return axiom;
}

void parse_left_side(std::string_view text, Production& production) {
  const std::size_t colon = text.find(':');
  const std::string_view head = text.substr(0, colon);
  std::size_t pos = skip_space(head, 0);
  const std::size_t length = symbol_length(head, pos);
  if (length == 0) fail(pos, "a production must start with the symbol it rewrites");
  production.predecessor = std::string(head.substr(pos, length));
  production.formals.clear();
  pos += length;
  if (pos < head.size() && head[pos] == '(') {
    std::vector<std::size_t> commas;
    const std::size_t close = closing_parenthesis(head, pos, commas);
    commas.push_back(close);
    std::size_t begin = pos + 1;
    for (std::size_t end : commas) {
      const std::string_view name = trim(head.substr(begin, end - begin));
      if (!is_identifier(name)) fail(begin, "formal parameters must be names, like P(m) or R(m, a)");
      if (name == "pi") fail(begin, "'pi' is a constant and cannot be a parameter name");
      if (std::find(production.formals.begin(), production.formals.end(), name) != production.formals.end())
        fail(begin, "parameter '" + std::string(name) + "' appears twice");
      production.formals.emplace_back(name);
      begin = end + 1;
    }
    pos = close + 1;
  }
  pos = skip_space(head, pos);
  if (pos != head.size()) fail(pos, "unexpected '" + std::string(1, head[pos]) + "' after the predecessor");
  production.condition.reset();
  if (colon == std::string_view::npos) return;
  const std::string_view condition = text.substr(colon + 1);
  if (trim(condition).empty()) fail(colon, "':' must be followed by a condition");
  production.condition = parse_piece(text, colon + 1, text.size());
  check_names(*production.condition, production, skip_space(text, colon + 1));
}

void parse_right_side(std::string_view text, Production& production) {
  std::size_t pos = skip_space(text, 0);
  production.probability = 1.0;
  if (pos < text.size() && text[pos] == '(') {
    std::vector<std::size_t> commas;
    const std::size_t close = closing_parenthesis(text, pos, commas);
    const Expression weight = parse_piece(text, pos + 1, close);
    if (!expression_variables(weight).empty()) fail(pos, "the probability must be a constant, like (0.5)");
    production.probability = evaluate(weight, {}, {});
    if (!(production.probability > 0) || !std::isfinite(production.probability))
      fail(pos, "the probability must be a positive number");
    pos = close + 1;
  }
  std::vector<std::size_t> columns;
  try {
    production.successor = parse_items(text.substr(pos), &columns);
  } catch (const ExpressionSyntaxError& error) {
    throw shift_column(error, pos);
  }
  for (std::size_t i = 0; i < production.successor.size(); ++i)
    for (const Expression& argument : production.successor[i].arguments)
      check_names(argument, production, pos + columns[i] + 1);
}

std::string format_successor(const std::vector<SuccessorItem>& successor) {
  std::string text;
  const SuccessorItem* previous = nullptr;
  for (const SuccessorItem& item : successor) {
    if (previous && needs_space(previous->symbol, !previous->arguments.empty(), item.symbol, !item.arguments.empty()))
      text += ' ';
    text += item.symbol;
    if (!item.arguments.empty()) {
      text += '(';
      for (std::size_t i = 0; i < item.arguments.size(); ++i) {
        if (i) text += ',';
        text += format_expression(item.arguments[i]);
      }
      text += ')';
    }
    previous = &item;
  }
  return text;
}

std::string format_left_side(const Production& production) {
  std::string text = production.predecessor;
  if (!production.formals.empty()) {
    text += '(';
    for (std::size_t i = 0; i < production.formals.size(); ++i) {
      if (i) text += ", ";
      text += production.formals[i];
    }
    text += ')';
  }
  if (production.condition) text += " : " + format_expression(*production.condition);
  return text;
}

std::string format_right_side(const Production& production, std::string_view empty) {
  std::string text;
  if (production.probability != 1.0) {
    text += '(';
    text += format_number(production.probability);
    text += ')';
  }
  const std::string successor = production.successor.empty() ? std::string(empty) : format_successor(production.successor);
  if (!text.empty() && !successor.empty()) text += ' ';
  return text + successor;
}

}  // namespace dg
