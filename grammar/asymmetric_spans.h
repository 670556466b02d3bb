#pragma once
// Where the asymmetry near a symmetric cell lies along a direction. A grid's first cut plane may
// cross symmetric cells that are within r of asymmetric ones (a damaged spot, a fin) as long as
// all that asymmetry lies on one side of the plane: the seam's r-neighbourhoods then still occur
// in the exemplar (see grid_rules.cpp).

#include "geometry/types.h"
#include "geometry/voxel_surface.h"

#include <limits>
#include <vector>

namespace dg {

/// Positions along a direction (model units) of the asymmetric cells near one symmetric cell;
/// empty (lo > hi) when none is within reach.
struct PositionSpan {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  bool empty() const { return lo > hi; }
};

/// For every cell with `symmetric[c]` set: the span of d . centre over the cells without the flag
/// that lie within intrinsic distance r of it (paths through symmetric cells, as in erode()).
/// Cells without the flag get an empty span.
std::vector<PositionSpan> asymmetric_spans(const VoxelSurface& surface, const std::vector<char>& symmetric, const Vec3& d,
                                           double r);

}  // namespace dg
