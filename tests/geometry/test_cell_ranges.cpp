#include "geometry/cell_ranges.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

using namespace dg;

TEST_CASE("cell ranges: every run of sorted keys is found with its range, absent keys are not", "[geometry]") {
  std::mt19937_64 random(7);
  std::vector<std::uint64_t> keys;
  for (int i = 0; i < 20000; ++i) keys.push_back(random() % 5000 * 0x100000001ULL);  // runs of repeated keys
  std::sort(keys.begin(), keys.end());
  std::map<std::uint64_t, CellRanges::Range> expected;
  for (std::uint32_t i = 0; i < keys.size(); ++i) {
    auto [it, added] = expected.emplace(keys[i], CellRanges::Range{i, i + 1});
    if (!added) it->second.second = i + 1;
  }
  CellRanges ranges;
  ranges.assign(keys.size(), [&](std::size_t i) { return keys[i]; });
  for (const auto& [key, range] : expected) {
    const CellRanges::Range* found = ranges.find(key);
    REQUIRE(found != nullptr);
    CHECK(*found == range);
  }
  std::size_t absent = 0;
  for (std::uint64_t key = 0; key < 5000; ++key) {
    CHECK(ranges.find(key * 0x100000001ULL + 1) == nullptr);  // between the stored keys
    if (expected.count(key * 0x100000001ULL)) continue;
    CHECK(ranges.find(key * 0x100000001ULL) == nullptr);  // a key of the range never drawn
    ++absent;
  }
  CHECK(absent > 0);
}

TEST_CASE("cell ranges: an empty or default table finds nothing", "[geometry]") {
  CellRanges unset;
  CHECK(unset.find(0) == nullptr);
  CellRanges empty;
  empty.assign(0, [](std::size_t) { return std::uint64_t{0}; });
  CHECK(empty.find(0) == nullptr);
  CHECK(empty.find(12345) == nullptr);
}
