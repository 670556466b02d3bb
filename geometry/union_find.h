#pragma once
// Disjoint sets over indices 0 .. n - 1 as a parent array (parent[i] == i at a root).

#include <cstdint>
#include <vector>

namespace dg {

/// Root of `v`'s set in `parent`, halving the path on the way (parent is updated).
std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t v);

}  // namespace dg
