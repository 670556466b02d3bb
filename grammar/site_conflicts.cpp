#include "grammar/site_conflicts.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <set>

namespace dg {

namespace {

// Trial `trial`'s order of the item indices: shuffled, the top-level items first, starting at
// top-level item trial mod `top_level`.
std::vector<std::size_t> trial_order(std::size_t count, std::size_t top_level, int trial, Random& random) {
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), 0);
  for (std::size_t i = order.size(); i > 1; --i)
    std::swap(order[i - 1], order[static_cast<std::size_t>(random.uniform() * static_cast<double>(i))]);
  const auto unfolded_from = std::stable_partition(order.begin(), order.end(), [&](std::size_t i) { return i < top_level; });
  const std::size_t start = static_cast<std::size_t>(trial) % top_level;
  std::rotate(order.begin(), std::find(order.begin(), unfolded_from, start), unfolded_from);
  return order;
}

// Whether `children[c]` clashes with another of `children` (only such a child is unfolded).
bool clashes_with_sibling(const std::vector<std::size_t>& children, std::size_t c,
                          const std::function<bool(std::size_t, std::size_t)>& clash) {
  for (std::size_t s = 0; s < children.size(); ++s)
    if (s != c && clash(children[c], children[s])) return true;
  return false;
}

}  // namespace

std::vector<std::vector<std::size_t>> random_independent_sets(const UnfoldedChildren& candidates, int trials, Random& random) {
  const std::vector<std::size_t>& items = candidates.items;
  const ConflictMatrix& conflict = candidates.conflict;
  if (items.empty()) return {{}};
  std::vector<std::vector<std::size_t>> sets;
  std::set<std::vector<std::size_t>> seen;
  for (int trial = 0; trial < trials; ++trial) {
    std::vector<std::size_t> chosen;
    for (std::size_t i : trial_order(items.size(), candidates.top_level, trial, random)) {
      bool free = true;
      for (std::size_t j : chosen) free = free && !conflict[i][j];
      if (free) chosen.push_back(i);
    }
    std::vector<std::size_t> set;
    for (std::size_t i : chosen) set.push_back(items[i]);
    std::sort(set.begin(), set.end());
    if (seen.insert(set).second) sets.push_back(set);
  }
  return sets;
}

UnfoldedChildren unfold_one_level(const std::vector<std::size_t>& children,
                                  const std::function<std::vector<std::size_t>(std::size_t)>& children_of,
                                  const std::function<bool(std::size_t, std::size_t)>& clash) {
  constexpr std::size_t kNoParent = std::numeric_limits<std::size_t>::max();
  UnfoldedChildren unfolded{children, {}, children.size()};
  std::vector<std::size_t> parent(children.size(), kNoParent);  // per item: its parent's item index
  for (std::size_t c = 0; c < children.size(); ++c) {
    if (!clashes_with_sibling(children, c, clash)) continue;  // its own productions place its children
    for (std::size_t g : children_of(children[c])) {
      unfolded.items.push_back(g);
      parent.push_back(c);
    }
  }
  const std::size_t n = unfolded.items.size();
  unfolded.conflict.assign(n, std::vector<char>(n, 0));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      unfolded.conflict[i][j] = unfolded.conflict[j][i] =
          parent[j] == i || parent[i] == j || clash(unfolded.items[i], unfolded.items[j]);
  return unfolded;
}

}  // namespace dg
