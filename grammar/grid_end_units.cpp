#include "grammar/grid_end_units.h"

#include "geometry/same_surface.h"
#include "geometry/slab_cut.h"
#include "geometry/submesh.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace dg {

int count_end_units(GridDirection& direction, const TriangleMesh& mesh, double tolerance,
                    std::span<const std::uint32_t> material_classes) {
  const Vec3& d = direction.direction;
  const double p = direction.pitch, start = direction.cut;
  const double snap = 1e-6 * tolerance;
  // Slab k lies between start + k p and start + (k + 1) p; each walk outward compares a slab with
  // the one it compared before, so cut meshes are kept per slab.
  const SlabTable slabs(mesh, d, start, p);
  std::map<int, TriangleMesh> meshes;
  auto area = [&](int k) { return slabs.area(k); };
  auto slab = [&](int k) -> const TriangleMesh& {
    auto [it, added] = meshes.try_emplace(k);
    if (!added) return it->second;
    TriangleMesh& cut = it->second = slabs.mesh(k, snap);
    if (material_classes.empty()) cut.materials.clear();
    for (std::uint32_t& m : cut.materials) m = material_classes[m];
    return it->second;
  };
  // Whether slab k, moved by the motion, is slab k + 1.
  auto copies_next = [&](int k) {
    const double a = area(k), b = area(k + 1);
    if (a <= 0.0 || std::abs(a - b) > kSameSlabArea * std::max(a, b)) return false;
    return same_surface(transformed(slab(k), direction.motion), slab(k + 1), tolerance);
  };
  int head = 0, tail = 0;
  while (copies_next(-head - 1)) ++head;
  while (copies_next(direction.count + tail - 1)) ++tail;
  direction.cut -= head * p;
  direction.count += head + tail;
  direction.head_units += head;
  direction.tail_units += tail;
  return head + tail;
}

}  // namespace dg
