#include "grammar/site_conflicts.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <set>

namespace dg {

std::vector<std::vector<std::size_t>> random_independent_sets(const std::vector<std::size_t>& items,
                                                              const ConflictMatrix& conflict, int trials,
                                                              Random& random) {
  if (items.empty()) return {{}};
  std::vector<std::vector<std::size_t>> sets;
  std::set<std::vector<std::size_t>> seen;
  for (int trial = 0; trial < trials; ++trial) {
    std::vector<std::size_t> order(items.size());
    std::iota(order.begin(), order.end(), 0);
    for (std::size_t i = order.size(); i > 1; --i)
      std::swap(order[i - 1], order[static_cast<std::size_t>(random.uniform() * static_cast<double>(i))]);
    const std::size_t start = static_cast<std::size_t>(trial) % items.size();
    std::rotate(order.begin(), std::find(order.begin(), order.end(), start), order.end());
    std::vector<std::size_t> chosen;
    for (std::size_t i : order) {
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
  UnfoldedChildren unfolded{children, {}};
  std::vector<std::size_t> parent(children.size(), kNoParent);  // per item: its parent's item index
  for (std::size_t c = 0; c < children.size(); ++c)
    for (std::size_t g : children_of(children[c])) {
      unfolded.items.push_back(g);
      parent.push_back(c);
    }
  const std::size_t n = unfolded.items.size();
  unfolded.conflict.assign(n, std::vector<char>(n, 0));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool related = parent[j] == i || parent[i] == j;
      unfolded.conflict[i][j] = unfolded.conflict[j][i] = related || clash(unfolded.items[i], unfolded.items[j]);
    }
  return unfolded;
}

}  // namespace dg
