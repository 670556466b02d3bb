#pragma once
// Connected parts of sets of voxel-surface cells.

#include "geometry/voxel_surface.h"

#include <cstdint>
#include <vector>

namespace dg {

/// Connected components (26-adjacency) of the cells whose flag is set in `mask` (one flag per
/// cell): each such cell's component, numbered from 0 in the order of their lowest cell; -1
/// elsewhere. `count` receives the number of components.
std::vector<std::int32_t> label_components(const VoxelSurface& surface, const std::vector<char>& mask, std::size_t& count);

}  // namespace dg
