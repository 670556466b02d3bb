#pragma once
// One- and two-letter D0L systems from unbranched turtle strings (the dragon curve's kind: two
// drawing symbols F and G that differ only in what they are rewritten to; or one letter whose
// block starts or ends with turns, as the Lévy curve's F -> +F--F+, which a prefix block of the
// drawing cannot show). The string is read as N segments with the net turn (in δ steps) before
// each; it is cut into groups of r segments, whose inner turns must show one or two patterns
// (F's block and G's block). The turns before
// and after both blocks are searched; which letters inside a block are F or G is read off the
// first group of that block one level up, and a hypothesis holds for as many levels as every
// coarser level again cuts into the two labelled blocks, so the string is σ^n(axiom) up to
// turns that add up between blocks (`+-` is no turn in a drawing).

#include <cstddef>
#include <optional>
#include <string>

namespace dg {

/// A D0L system on the letters F and G (both draw): axiom, `F -> f_successor`,
/// `G -> g_successor` (empty: no G), applied `iterations` times. The axiom's leading turn is
/// left out: the start heading is the one that draws `text` plus `start_turn` steps.
struct ChainGrammar {
  std::string axiom;
  std::string f_successor, g_successor;
  int iterations = 0;
  std::size_t length = 0;  ///< grammar length: axiom + successors + distinct symbols
  int start_turn = 0;      ///< the axiom's leading turn steps, left to the start heading
};

/// The shortest one- or two-letter system whose derivation, drawn with F and G as segments and
/// net turns, is `text` (symbols F + - only; anything else gives nothing), each turn of `text`
/// counted as `turn_factor` steps (2: the system turns by half the drawing's δ); turns wrap
/// around at `full_turn` steps (360 degrees; 0 when no whole number of steps makes one). Blocks of 2 to
/// `max_block_letters` letters, turns before and after a block of at most `max_edge_turns`
/// steps. Nothing when no hypothesis explains the string with at least one rewriting level.
std::optional<ChainGrammar> recover_chain_grammar(const std::string& text, int turn_factor = 1, int full_turn = 0,
                                                  int max_block_letters = 8, int max_edge_turns = 2);

}  // namespace dg
