#pragma once
// Pruning a context-free shape grammar after its productions are made: non-terminals no
// derivation reaches, and alternatives that would only move the whole model.

#include "grammar/context_free.h"

#include <cstddef>
#include <vector>

namespace dg {

/// Flags (one per non-terminal) those a derivation can reach from `starts` through the
/// productions of `grammar`, the starts included.
std::vector<char> reachable_nonterminals(const ContextFreeGrammar& grammar, std::vector<std::size_t> starts);

/// Drops the non-terminals that no derivation reaches from the axiom, with their productions;
/// the rest are renumbered in their order and renamed N1, N2, ... Returns how many went.
std::size_t drop_unreachable_nonterminals(ContextFreeGrammar& grammar);

/// How a docker cut at one location of a non-terminal and put at another moves the model.
enum class SwapMotion : char {
  none,       ///< it varies the model: the rest around the locations differs
  in_place,   ///< it rebuilds the exemplar moved onto its own bounding box (a half turn of a slab)
  elsewhere,  ///< it rebuilds the exemplar moved off its bounding box
};

/// Drops the productions of non-terminals whose swaps move the model (`swaps`, one per
/// non-terminal) that rebuild no slot of the exemplar (no slot names them as its original
/// production): children come along with the docker they lie in, so the result is the exemplar
/// moved. When the motion keeps the model on its own bounding box (a half turn about its
/// middle), an alternative whose children reach a non-terminal with a choice is kept; when it
/// moves the model off it, none is (the Quaternius bank's and the Hochhaus Asemwald's variants
/// were the model shifted by (339.2, 0, -54) and (-73, 0, 2.3)). Non-terminals stay; productions
/// are renumbered. Returns how many productions went.
std::size_t drop_alternatives_moving_the_model(ContextFreeGrammar& grammar, const std::vector<SwapMotion>& swaps);

}  // namespace dg
