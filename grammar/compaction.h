#pragma once
// Compaction of a bracketed turtle string into a short L-system (after Guo et al. 2020 §4.2,
// Algorithm 1): the string is searched for the maximal repeated block that, written as one
// symbol, turns the whole string into a copy of itself one level coarser. Replacing every
// occurrence of the block by `F` is repeated while it succeeds; the result is the axiom, the
// block is the successor of the rule `F -> block`, and the number of replacements the
// iteration count. Among all candidate blocks the one with the shortest grammar wins.

#include <cstddef>
#include <optional>
#include <string>

namespace dg {

/// A compact single-rule grammar: axiom, `F -> successor`, iterations (0: no rule).
struct CompactGrammar {
  std::string axiom;
  std::string successor;
  int iterations = 0;
  std::size_t length = 0;  ///< grammar length (axiom + successor + distinct symbols)
};

/// Grammar length of axiom + rule `F -> successor` (when iterations > 0), one character per
/// symbol: symbols of the axiom and successor plus the distinct symbols (predecessor included).
std::size_t compact_grammar_length(const std::string& axiom, const std::string& successor, int iterations);

/// The block with its trailing bracketed branches unbracketed (`FF[+F][-F]` -> `FF[+F]-F`): how
/// the block is written at the end of a branch, where nothing follows it.
std::string elide_trailing_branches(const std::string& block);

/// `text` with every occurrence of `block` (or of its elided form right before `]` or the end)
/// replaced by `F`, scanning left to right; nothing when an `F` is left that no block covers.
std::optional<std::string> replace_blocks(const std::string& text, const std::string& block);

/// The shortest grammar found: candidate blocks are the balanced prefixes of `text` of 2 to
/// `max_block` symbols that start with `F` and hold at least two `F`. Without any that applies,
/// the grammar is `text` itself as axiom with no rule.
CompactGrammar compact_turtle_string(const std::string& text, std::size_t max_block = 200);

}  // namespace dg
