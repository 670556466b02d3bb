#pragma once
// A read-only table from 64-bit cell keys to index ranges, for spatial grids whose items are
// sorted by cell: open addressing with linear probing in a power-of-two table at most half full,
// so a lookup is a multiply, a shift and usually one cache line (a node-based hash map costs a
// division and a pointer chase per lookup, which dominated verify's neighbourhood queries).

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace dg {

class CellRanges {
 public:
  using Range = std::pair<std::uint32_t, std::uint32_t>;  ///< [first, second) of the sorted items

  /// Indexes n items whose keys key_at(0 .. n-1) are sorted: each run of equal keys is one range.
  template <class KeyAt>
  void assign(std::size_t n, const KeyAt& key_at) {
    std::size_t runs = 0;
    for (std::size_t i = 0; i < n; ++i) runs += i == 0 || key_at(i) != key_at(i - 1);
    reset(runs);
    for (std::size_t begin = 0; begin < n;) {
      std::size_t end = begin + 1;
      while (end < n && key_at(end) == key_at(begin)) ++end;
      insert(key_at(begin), {static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end)});
      begin = end;
    }
  }

  /// The range of `key`, or nullptr when no item has it.
  const Range* find(std::uint64_t key) const {
    if (ranges_.empty()) return nullptr;
    for (std::size_t slot = slot_of(key);; slot = (slot + 1) & mask_) {
      if (ranges_[slot].second == 0) return nullptr;  // an empty slot: ranges are never empty
      if (keys_[slot] == key) return &ranges_[slot];
    }
  }

 private:
  void reset(std::size_t runs);
  void insert(std::uint64_t key, Range range);
  std::size_t slot_of(std::uint64_t key) const {
    return static_cast<std::size_t>((key * 0x9e3779b97f4a7c15ULL) >> shift_);
  }

  std::vector<std::uint64_t> keys_;
  std::vector<Range> ranges_;  // second == 0 marks an empty slot
  std::size_t mask_ = 0;
  int shift_ = 64;
};

}  // namespace dg
