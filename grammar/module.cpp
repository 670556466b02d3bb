#include "grammar/module.h"

#include <cctype>

namespace dg {

namespace {

bool is_letter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

}  // namespace

std::size_t symbol_length(std::string_view text, std::size_t pos) {
  if (pos >= text.size()) return 0;
  const char c = text[pos];
  const auto byte = static_cast<unsigned char>(c);
  if (byte <= ' ' || byte >= 0x7f || c == '(' || c == ')' || c == ',') return 0;
  if (text.substr(pos, 3) == "cut" && (pos + 3 == text.size() || !std::isalnum(static_cast<unsigned char>(text[pos + 3]))))
    return 3;
  std::size_t end = pos + 1;
  if (c == '?') {
    while (end < text.size() && is_letter(text[end])) ++end;
    return end - pos;
  }
  if (is_letter(c))
    while (end < text.size() && is_digit(text[end])) ++end;
  return end - pos;
}

bool is_symbol_name(std::string_view name) { return !name.empty() && symbol_length(name, 0) == name.size(); }

std::string format_module(const Module& module) {
  std::string text = module.symbol;
  if (module.parameters.empty()) return text;
  text += '(';
  for (std::size_t i = 0; i < module.parameters.size(); ++i) {
    if (i) text += ',';
    text += format_number(module.parameters[i]);
  }
  return text + ')';
}

bool needs_space(std::string_view previous, bool previous_has_arguments, std::string_view next,
                 bool next_has_arguments) {
  if (previous == "[" || next == "]") return false;
  if (previous_has_arguments || next_has_arguments || previous.size() != 1 || next.size() != 1) return true;
  if (previous == "u" && next == "t") return true;  // `c u t` written together would read as `cut`
  return symbol_length(std::string(previous) + std::string(next), 0) != 1;
}

std::string format_modules(const std::vector<Module>& modules) {
  std::string text;
  const Module* previous = nullptr;
  for (const Module& module : modules) {
    if (previous && needs_space(previous->symbol, !previous->parameters.empty(), module.symbol,
                                !module.parameters.empty()))
      text += ' ';
    text += format_module(module);
    previous = &module;
  }
  return text;
}

}  // namespace dg
