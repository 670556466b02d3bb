#pragma once
// D0L systems with a non-drawing apex symbol, `X -> u` and `F -> F^m` with axiom X (the kind of
// Prusinkiewicz and Lindenmayer's plants 1.24d-f, e.g. X -> F[+X][-X]FX, F -> FF): drawn after n
// steps, each X of u stands for the whole drawing of n-1 steps and each F of u for a run of
// m^(n-1) segments. The drawing of n-1 steps is taken from a branch of the turtle string, u is read
// off by replacing its copies by X and the runs by F, and the hypothesis holds when deriving it
// gives the same drawing (compared as canonical turtle strings).

#include <cstddef>
#include <optional>
#include <string>

namespace dg {

/// `X -> apex_successor`, `F -> F^m`, axiom X, `iterations` steps; X does not draw.
struct ApexGrammar {
  std::string apex_successor;
  int m = 2;
  int iterations = 0;
  std::size_t length = 0;  ///< grammar length: axiom + successors + distinct symbols
};

/// The shortest apex system whose drawing, written by canonical_turtle_string with
/// `descending_turns`, is `text` (a string written that way, symbols F + - [ ]). m from 2 to
/// `max_m`. Nothing when no hypothesis derives the string.
std::optional<ApexGrammar> recover_apex_grammar(const std::string& text, bool descending_turns, int max_m = 3);

}  // namespace dg
