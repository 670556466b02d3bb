#pragma once
// Resolving conflicts between the docking sites a docker holds (paper 001 §3.4.2): random
// maximal independent sets of the conflict graph, over the children of a node of the inclusion
// tree with one hierarchy level unfolded.

#include "grammar/random.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace dg {

/// A conflict graph: symmetric adjacency, conflict[i][j] != 0 when items i and j clash.
using ConflictMatrix = std::vector<std::vector<char>>;

/// Up to `trials` distinct maximal independent sets of the graph over `items`, in trial order,
/// each sorted ascending: trial k shuffles the items, starts at item k mod n, and adds every
/// item that conflicts with none chosen so far (the paper samples 10). No items: one empty set.
std::vector<std::vector<std::size_t>> random_independent_sets(const std::vector<std::size_t>& items,
                                                              const ConflictMatrix& conflict, int trials,
                                                              Random& random);

/// Candidate children of a node with one hierarchy level unfolded: `children`, then the
/// children of each (`children_of`), with their conflict graph from `clash`. A child and its own
/// children always conflict (choosing the child places them through its own productions); a
/// grandchild is chosen only where its parent is left out.
struct UnfoldedChildren {
  std::vector<std::size_t> items;
  ConflictMatrix conflict;
};
UnfoldedChildren unfold_one_level(const std::vector<std::size_t>& children,
                                  const std::function<std::vector<std::size_t>(std::size_t)>& children_of,
                                  const std::function<bool(std::size_t, std::size_t)>& clash);

}  // namespace dg
