#pragma once
// Sets of voxel-surface cells, as ascending index lists or as one flag per cell.

#include <cstdint>
#include <vector>

namespace dg {

/// One flag per cell (`count` cells), set for the listed cells.
inline std::vector<char> mask_of(const std::vector<std::uint32_t>& cells, std::size_t count) {
  std::vector<char> mask(count, 0);
  for (std::uint32_t c : cells) mask[c] = 1;
  return mask;
}

/// Share of the listed cells whose flag is set in `mask` (0 for an empty list).
inline double share_inside(const std::vector<std::uint32_t>& cells, const std::vector<char>& mask) {
  if (cells.empty()) return 0.0;
  std::size_t inside = 0;
  for (std::uint32_t c : cells) inside += mask[c] ? 1 : 0;
  return static_cast<double>(inside) / static_cast<double>(cells.size());
}

}  // namespace dg
