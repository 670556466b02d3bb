#include "geometry/cell_ranges.h"

namespace dg {

void CellRanges::reset(std::size_t runs) {
  std::size_t capacity = 2;
  int bits = 1;
  while (capacity < 2 * runs) {
    capacity *= 2;
    ++bits;
  }
  keys_.assign(capacity, 0);
  ranges_.assign(capacity, Range{0, 0});
  mask_ = capacity - 1;
  shift_ = 64 - bits;
}

void CellRanges::insert(std::uint64_t key, Range range) {
  std::size_t slot = slot_of(key);
  while (ranges_[slot].second != 0) slot = (slot + 1) & mask_;
  keys_[slot] = key;
  ranges_[slot] = range;
}

}  // namespace dg
