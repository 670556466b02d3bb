#pragma once
// Two-letter D0L systems from unbranched turtle strings (the dragon curve's kind: two drawing
// symbols F and G that differ only in what they are rewritten to). The string is read as N
// segments with the net turn (in δ steps) before each; it is cut into groups of r segments,
// whose inner turns must show exactly two patterns (F's block and G's block). The turns before
// and after both blocks are searched; which letters inside a block are F or G is read off the
// first group of that block one level up, and a hypothesis holds for as many levels as every
// coarser level again cuts into the two labelled blocks, so the string is σ^n(axiom) up to
// turns that add up between blocks (`+-` is no turn in a drawing).

#include <cstddef>
#include <optional>
#include <string>

namespace dg {

/// A D0L system on the letters F and G (both draw): axiom, `F -> f_successor`,
/// `G -> g_successor`, applied `iterations` times.
struct ChainGrammar {
  std::string axiom;
  std::string f_successor, g_successor;
  int iterations = 0;
  std::size_t length = 0;  ///< grammar length: axiom + successors + distinct symbols
};

/// The shortest two-letter system whose derivation, drawn with F and G as segments and net
/// turns, is `text` (symbols F + - only; anything else gives nothing). Blocks of 2 to
/// `max_block_letters` letters, turns before and after a block of at most `max_edge_turns`
/// steps. Nothing when no hypothesis explains the string with at least one rewriting level.
std::optional<ChainGrammar> recover_chain_grammar(const std::string& text, int max_block_letters = 8,
                                                  int max_edge_turns = 2);

}  // namespace dg
