#include "grammar/cell_components.h"

namespace dg {

std::vector<std::int32_t> label_components(const VoxelSurface& surface, const std::vector<char>& mask, std::size_t& count) {
  std::vector<std::int32_t> label(surface.cell_count(), -1);
  count = 0;
  std::vector<std::uint32_t> queue;
  for (std::uint32_t start = 0; start < surface.cell_count(); ++start) {
    if (!mask[start] || label[start] >= 0) continue;
    const auto id = static_cast<std::int32_t>(count++);
    label[start] = id;
    queue.assign(1, start);
    for (std::size_t head = 0; head < queue.size(); ++head)
      for (std::uint32_t n : surface.neighbours(queue[head]))
        if (mask[n] && label[n] < 0) {
          label[n] = id;
          queue.push_back(n);
        }
  }
  return label;
}

}  // namespace dg
