#pragma once
// The textual pieces shared by the L-system text and JSON forms: a predecessor with optional
// condition (`P(m) : m>0`), a right side with optional probability (`(0.5) F[+F]F`), an axiom.
// Errors are ExpressionSyntaxError with a 1-based column inside the piece that was parsed.

#include "grammar/module.h"
#include "grammar/production.h"

#include <string>
#include <string_view>
#include <vector>

namespace dg {

/// Parses a successor `A f(27.5) *(0.993) P(m-1)` or `F[+F]F`; an empty text or `ε` is the
/// empty successor. Arguments follow their symbol without a space.
std::vector<SuccessorItem> parse_successor(std::string_view text);

/// Parses an axiom: like a successor, but every argument must be a constant expression.
std::vector<Module> parse_axiom(std::string_view text);

/// Parses a left side `P(m, n) : condition` or `F` into `production` (predecessor, formals,
/// condition); the successor and probability are left alone.
void parse_left_side(std::string_view text, Production& production);

/// Parses a right side `(0.5) successor` or `successor` into `production` (successor and
/// probability; the probability is 1 when not given). Checks that every name the successor
/// reads is one of the production's formals, so parse_left_side comes first.
void parse_right_side(std::string_view text, Production& production);

/// Text of a successor (`A f(27.5) P(m-1)`, `F[+F]F`; "" when empty).
std::string format_successor(const std::vector<SuccessorItem>& successor);

/// Text of a production's left side: `P(m) : m>0`, `F`.
std::string format_left_side(const Production& production);

/// Text of a production's right side: `(0.5) F[+F]F` (probability only when it is not 1);
/// `empty` stands for the empty successor (the text form writes `ε`, the JSON form "").
std::string format_right_side(const Production& production, std::string_view empty);

/// A copy of `error` with its column moved by `offset` characters (for pieces cut out of a line).
ExpressionSyntaxError shift_column(const ExpressionSyntaxError& error, std::size_t offset);

}  // namespace dg
