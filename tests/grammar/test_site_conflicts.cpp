// Conflict resolution among the docking sites of one docker (paper 001 §3.4.2).

#include "grammar/site_conflicts.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <utility>

namespace {

using Sets = std::vector<std::vector<std::size_t>>;

bool contains(const Sets& sets, const std::vector<std::size_t>& set) {
  return std::find(sets.begin(), sets.end(), set) != sets.end();
}

}  // namespace

TEST_CASE("random independent sets are maximal, conflict-free, distinct and seeded", "[grammar][context_free]") {
  // A path 0 - 1 - 2 - 3: its maximal independent sets are {0, 2}, {0, 3} and {1, 3}.
  dg::UnfoldedChildren path{{10, 11, 12, 13}, dg::ConflictMatrix(4, std::vector<char>(4, 0)), 4};
  for (std::size_t i = 0; i + 1 < 4; ++i) path.conflict[i][i + 1] = path.conflict[i + 1][i] = 1;
  dg::Random random(7);
  const Sets sets = dg::random_independent_sets(path, 10, random);
  CHECK(sets.size() == 3);
  CHECK(contains(sets, {10, 12}));
  CHECK(contains(sets, {10, 13}));
  CHECK(contains(sets, {11, 13}));
  dg::Random again(7);
  CHECK(dg::random_independent_sets(path, 10, again) == sets);
  dg::Random empty_random(1);
  CHECK(dg::random_independent_sets({}, 10, empty_random) == Sets{{}});
}

TEST_CASE("one unfolded level lets a grandchild take the place of its conflicting parent", "[grammar][context_free]") {
  // Node children 1 and 2 clash; child 1 holds site 3 (inside its docker), which clashes with
  // nothing else, and site 3 holds site 4 (two levels down: never unfolded).
  const std::map<std::size_t, std::vector<std::size_t>> tree{{1, {3}}, {2, {}}, {3, {4}}, {4, {}}};
  auto children_of = [&](std::size_t s) { return tree.at(s); };
  auto clash = [](std::size_t a, std::size_t b) { return (a == 1 && b == 2) || (a == 2 && b == 1); };
  const dg::UnfoldedChildren unfolded = dg::unfold_one_level({1, 2}, children_of, clash);
  CHECK(unfolded.items == std::vector<std::size_t>{1, 2, 3});
  CHECK(unfolded.conflict[0][2] == 1);  // a child and its own child
  CHECK(unfolded.conflict[1][2] == 0);
  dg::Random random(3);
  const Sets sets = dg::random_independent_sets(unfolded, 10, random);
  // Leaving child 1 out for child 2 keeps site 3 (without unfolding: {1} and {2} only).
  CHECK(sets.size() == 2);
  CHECK(contains(sets, {1}));
  CHECK(contains(sets, {2, 3}));
}

TEST_CASE("a child that clashes with no sibling is not unfolded", "[grammar][context_free]") {
  // Children 1 and 2 clash; child 5 clashes with nothing. Child 1 holds site 3, child 5 holds
  // site 6. Unfolding 5 would only give productions that repeat 5's own one level up (pipe tree
  // of 100k triangles: 27 -> 35 productions, variants twice as big, choices colliding).
  const std::map<std::size_t, std::vector<std::size_t>> tree{{1, {3}}, {2, {}}, {3, {}}, {5, {6}}, {6, {}}};
  auto children_of = [&](std::size_t s) { return tree.at(s); };
  auto clash = [](std::size_t a, std::size_t b) { return (a == 1 && b == 2) || (a == 2 && b == 1); };
  const dg::UnfoldedChildren unfolded = dg::unfold_one_level({1, 2, 5}, children_of, clash);
  CHECK(unfolded.items == std::vector<std::size_t>{1, 2, 5, 3});
  dg::Random random(3);
  const Sets sets = dg::random_independent_sets(unfolded, 10, random);
  CHECK(sets.size() == 2);
  CHECK(contains(sets, {1, 5}));
  CHECK(contains(sets, {2, 3, 5}));
}

TEST_CASE("a grandchild is not chosen in place of a parent that nothing chosen clashes with", "[grammar][context_free]") {
  // Children 1 and 2 clash; child 1 holds site 3, which clashes with 2 as well. {3} alone leaves
  // 1 out for its own child only: the same as 1 with its production {3}, one level up (pipe
  // tree of 100k triangles: N6 -> N5 besides N6 -> N4 and N4 -> N5; variants twice as big).
  const std::map<std::size_t, std::vector<std::size_t>> tree{{1, {3}}, {2, {}}, {3, {}}};
  auto children_of = [&](std::size_t s) { return tree.at(s); };
  const std::set<std::pair<std::size_t, std::size_t>> clashing{{1, 2}, {2, 3}};
  auto clash = [&](std::size_t a, std::size_t b) { return clashing.count({std::min(a, b), std::max(a, b)}) > 0; };
  const dg::UnfoldedChildren unfolded = dg::unfold_one_level({1, 2}, children_of, clash);
  REQUIRE(unfolded.items == std::vector<std::size_t>{1, 2, 3});
  CHECK(unfolded.top_level == 2);      // site 3 is held by a child: listed after the children
  CHECK(unfolded.conflict[2][0] == 1);  // and conflicts with its holder
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    dg::Random random(seed);
    const Sets sets = dg::random_independent_sets(unfolded, 10, random);
    CHECK(sets == Sets{{1}, {2}});
  }
}
