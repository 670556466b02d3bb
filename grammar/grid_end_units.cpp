#include "grammar/grid_end_units.h"

#include "geometry/same_surface.h"
#include "geometry/slab_cut.h"
#include "geometry/submesh.h"

#include <algorithm>
#include <cmath>

namespace dg {
namespace {

// Relative difference of surface area below which two slabs count as equally large.
constexpr double kSameSlabArea = 1e-4;

}  // namespace

int count_end_units(GridDirection& direction, const TriangleMesh& mesh, double tolerance) {
  const Vec3& d = direction.direction;
  const double p = direction.pitch;
  const double snap = 1e-6 * tolerance;
  // Whether the slab [lo, lo + p], moved by the motion, is the slab [lo + p, lo + 2p].
  auto copies_next = [&](double lo) {
    const double a = area_between_planes(mesh, d, lo, lo + p), b = area_between_planes(mesh, d, lo + p, lo + 2 * p);
    if (a <= 0.0 || std::abs(a - b) > kSameSlabArea * std::max(a, b)) return false;
    return same_surface(transformed(mesh_between_planes(mesh, d, lo, lo + p, snap), direction.motion),
                        mesh_between_planes(mesh, d, lo + p, lo + 2 * p, snap), tolerance);
  };
  int added = 0;
  while (copies_next(direction.cut - p)) {
    direction.cut -= p;
    ++direction.count;
    ++direction.head_units;
    ++added;
  }
  while (copies_next(direction.cut + (direction.count - 1) * p)) {
    ++direction.count;
    ++direction.tail_units;
    ++added;
  }
  return added;
}

}  // namespace dg
