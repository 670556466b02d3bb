#include "grammar/seam_surface.h"

#include <algorithm>
#include <cmath>

namespace dg {

bool SeamSurface::near(const Vec3& p, double tolerance) const {
  if (kind == Kind::plane) return std::abs(normal.dot(p) - offset) <= tolerance;
  if (faces.empty() || !(eps > 0.0)) return false;
  const Vec3 g = p / eps;  // grid units
  const double reach = tolerance / eps;
  auto gap = [](double x, double lo) { return std::max({0.0, lo - x, x - (lo + 1.0)}); };
  for (int axis = 0; axis < 3; ++axis) {
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    for (auto k = static_cast<std::int32_t>(std::ceil(g[axis] - reach)); k <= std::floor(g[axis] + reach); ++k)
      for (auto j = static_cast<std::int32_t>(std::floor(g[b] - reach)); j <= std::floor(g[b] + reach); ++j)
        for (auto l = static_cast<std::int32_t>(std::floor(g[c] - reach)); l <= std::floor(g[c] + reach); ++l) {
          VoxelFace face;
          face.axis = axis;
          face.voxel[axis] = k;
          face.voxel[b] = j;
          face.voxel[c] = l;
          if (!std::binary_search(faces.begin(), faces.end(), face)) continue;
          const double d = std::hypot(g[axis] - k, gap(g[b], j), gap(g[c], l));
          if (d <= reach) return true;
        }
  }
  return false;
}

}  // namespace dg
