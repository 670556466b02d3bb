#pragma once
// The L-system text form (documented in docs/lsystem-syntax.md), close to cpfg / L-Py:
//
//   # comment (also // comment)
//   axiom: P(336)
//   angle: 8.5
//   P(m) : m>0 -> A f(27.5) *(0.993) +(8.5) P(m-1)
//   P(m) : m==0 -> ε
//   F -> (0.5) F[+F]F          stochastic alternatives carry a weight in parentheses

#include "grammar/lsystem.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace dg {

/// Parses the text form. `source` names the input in error messages, which read
/// "source:line: problem" (dg::InputError).
LSystem parse_lsystem_text(std::string_view text, const std::string& source);

/// Reads and parses a text file; InputError when it cannot be read or is malformed.
LSystem read_lsystem_text(const std::filesystem::path& path);

/// The text form of `system`; parse_lsystem_text reads it back to an equal LSystem.
std::string format_lsystem_text(const LSystem& system);

/// Reads a whole file into a string; InputError "path: cannot read" when that fails.
std::string read_text_file(const std::filesystem::path& path);

}  // namespace dg
