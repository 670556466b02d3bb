#pragma once
// Symbol replacement, an editing operation of Št'ava et al. 2010 §6: a terminal or non-terminal
// is replaced by another symbol wherever it is produced, e.g. a whole group of elements (a
// non-terminal) by one element (a terminal).

#include "grammar/lsystem.h"

#include <string>

namespace dg {

/// Renames `from` to `to` in the axiom and in every successor, keeping the arguments.
/// Predecessors stay, so the productions of `from` simply stop being used.
/// Returns how many occurrences were replaced.
std::size_t replace_symbol(LSystem& system, const std::string& from, const std::string& to);

}  // namespace dg
