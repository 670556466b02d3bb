#pragma once
// Modules (a symbol with parameter values, e.g. `P(336)` or `F`) and successor items (a symbol
// with parameter expressions, e.g. `P(m-1)`). Symbols are names: one character (`F`, `+`, `[`),
// a letter followed by digits (`P0`, `R12`), a query name `?` + letters (`?X`, reserved for
// the environment queries of Open L-systems), or the word `cut` (ends a branch, Open L-systems)
// when no letter or digit follows it.

#include "grammar/expression.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace dg {

/// One element of a derived string: symbol name and actual parameter values.
struct Module {
  std::string symbol;
  std::vector<double> parameters;

  friend bool operator==(const Module&, const Module&) = default;
};

/// One element of a production's successor: symbol name and one expression per parameter,
/// evaluated with the predecessor's formal parameters bound.
struct SuccessorItem {
  std::string symbol;
  std::vector<Expression> arguments;

  friend bool operator==(const SuccessorItem&, const SuccessorItem&) = default;
};

/// Length in characters of the symbol name that starts at text[pos] (0 when text[pos] cannot
/// start a symbol: end of text, whitespace, control or non-ASCII bytes, `(`, `)` or `,`).
std::size_t symbol_length(std::string_view text, std::size_t pos);

/// True when `name` is one whole symbol name by the rules above.
bool is_symbol_name(std::string_view name);

/// Text of one module: `F`, `P(336)`, `f(27.5)`.
std::string format_module(const Module& module);

/// Whether printed text puts a space between two neighbouring items (symbol names, and whether
/// each has arguments): none after `[` or before `]`, none between one-character symbols without
/// arguments that still read back as two symbols (`F+`, but `F 0` since `F0` is one symbol).
bool needs_space(std::string_view previous, bool previous_has_arguments, std::string_view next,
                 bool next_has_arguments);

/// Text of a module string; modules with parameters are separated by spaces (`A f(27.5) P(3)`),
/// runs of parameterless one-character symbols are written together (`F[+F]F`).
std::string format_modules(const std::vector<Module>& modules);

}  // namespace dg
