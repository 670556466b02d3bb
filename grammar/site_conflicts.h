#pragma once
// Resolving conflicts between the docking sites a docker holds (paper 001 §3.4.2): random
// maximal independent sets of the conflict graph, over the children of a node of the inclusion
// tree with one hierarchy level unfolded.

#include "geometry/random.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace dg {

/// A conflict graph: symmetric adjacency, conflict[i][j] != 0 when items i and j clash.
using ConflictMatrix = std::vector<std::vector<char>>;

/// Items to choose sets from, with their conflict graph. The first `top_level` items are a
/// node's own children; the rest were unfolded from them (each conflicts with its holder).
struct UnfoldedChildren {
  std::vector<std::size_t> items;
  ConflictMatrix conflict;
  std::size_t top_level = 0;
};

/// Up to `trials` distinct maximal independent sets of `candidates`, in trial order, each sorted
/// ascending: trial k shuffles the items, starts at top-level item k mod their count, and adds
/// every item that conflicts with none chosen so far (the paper samples 10). Unfolded items come
/// after all top-level ones, so one is chosen only where its holder was left out for a conflict
/// with another chosen item, never in place of a holder that clashes with nothing chosen (that
/// set would repeat the holder's own production one level up). No items: one empty set.
std::vector<std::vector<std::size_t>> random_independent_sets(const UnfoldedChildren& candidates, int trials, Random& random);

/// Candidate children of a node with one hierarchy level unfolded: `children` (top level), then
/// the children (`children_of`) of each child that clashes with a sibling, with their conflict
/// graph from `clash`. A child and its own children always conflict (choosing the child places
/// them through its own productions); a grandchild is chosen only where its parent is left out
/// for a conflict. A child that clashes with no sibling is never left out for a conflict, so its
/// children are not unfolded: they would only repeat its own productions one level up (more
/// slots per production, bigger and slower derivations; paper 001 §3.4.2 unfolds overlapping
/// nodes only).
UnfoldedChildren unfold_one_level(const std::vector<std::size_t>& children,
                                  const std::function<std::vector<std::size_t>(std::size_t)>& children_of,
                                  const std::function<bool(std::size_t, std::size_t)>& clash);

}  // namespace dg
