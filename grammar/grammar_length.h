#pragma once
// Grammar length, the size measure of the 2D corpus and of Guo et al. 2020.

#include "grammar/lsystem.h"

#include <cstddef>

namespace dg {

/// Symbols in the axiom + symbols in all successors + number of distinct symbol names
/// (predecessors included). A module with arguments, like `P(m-1)`, counts as one symbol.
std::size_t grammar_length(const LSystem& system);

}  // namespace dg
