#include "grammar/same_production.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <tuple>

namespace dg {
namespace {

using CellKey = std::array<std::int64_t, 3>;

// The cells (cubes of edge `cell`, model units) that points of `mesh`'s surface fall in, sampled
// on each triangle in rows parallel to its longest edge, at most cell / 2 apart along and across
// them (so a sliver costs as few samples as its area needs); sorted, without repeats.
std::vector<CellKey> surface_cells(const TriangleMesh& mesh, double cell) {
  std::vector<CellKey> cells;
  auto add = [&](const Vec3& p) {
    cells.push_back({static_cast<std::int64_t>(std::floor(p.x() / cell)), static_cast<std::int64_t>(std::floor(p.y() / cell)),
                     static_cast<std::int64_t>(std::floor(p.z() / cell))});
  };
  const double spacing = 0.5 * cell;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    auto [a, b, c] = mesh.corners(t);
    // Make a-b the longest edge.
    if ((c - b).norm() > (b - a).norm() && (c - b).norm() >= (a - c).norm()) std::tie(a, b, c) = std::tuple{b, c, a};
    else if ((a - c).norm() > (b - a).norm()) std::tie(a, b, c) = std::tuple{c, a, b};
    const double length = (b - a).norm();
    const double height = length > 0.0 ? (b - a).cross(c - a).norm() / length : (c - a).norm();
    const int rows = std::max(1, static_cast<int>(std::ceil(height / spacing)));
    for (int k = 0; k <= rows; ++k) {
      const double s = static_cast<double>(k) / rows;  // row from a-b (s = 0) to c (s = 1)
      const Vec3 from = a + s * (c - a), to = b + s * (c - b);
      const int steps = std::max(1, static_cast<int>(std::ceil((1.0 - s) * length / spacing)));
      for (int i = 0; i <= steps; ++i) add(from + (static_cast<double>(i) / steps) * (to - from));
    }
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return cells;
}

// Every cell of `a` is a cell of `b` or touches one (26-neighbourhood); both sorted.
bool cells_covered(const std::vector<CellKey>& a, const std::vector<CellKey>& b) {
  for (const CellKey& k : a) {
    bool near = false;
    for (std::int64_t dx = -1; dx <= 1 && !near; ++dx)
      for (std::int64_t dy = -1; dy <= 1 && !near; ++dy)
        for (std::int64_t dz = -1; dz <= 1 && !near; ++dz)
          near = std::binary_search(b.begin(), b.end(), CellKey{k[0] + dx, k[1] + dy, k[2] + dz});
    if (!near) return false;
  }
  return true;
}

// Surface area of `mesh` per material index (one entry for a mesh without materials).
std::map<std::uint32_t, double> area_by_material(const TriangleMesh& mesh) {
  std::map<std::uint32_t, double> areas;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    areas[mesh.has_materials() ? mesh.materials[t] : 0] += 0.5 * mesh.area_vector(t).norm();
  return areas;
}

}  // namespace

bool same_production(const ShapeProduction& a, const ShapeProduction& b, double tolerance) {
  if (a.lhs != b.lhs || a.children.size() != b.children.size() || a.terminal.triangles.empty() != b.terminal.triangles.empty())
    return false;
  for (std::size_t i = 0; i < a.children.size(); ++i) {
    const ChildSlot &x = a.children[i], &y = b.children[i];
    if (x.nonterminal != y.nonterminal || x.original_production != y.original_production ||
        !same_motion(x.placement, y.placement, Vec3::Zero(), tolerance))
      return false;
  }
  if (a.terminal.triangles.empty()) return true;
  const std::map<std::uint32_t, double> areas_a = area_by_material(a.terminal), areas_b = area_by_material(b.terminal);
  if (areas_a.size() != areas_b.size()) return false;
  for (auto x = areas_a.begin(), y = areas_b.begin(); x != areas_a.end(); ++x, ++y)
    if (x->first != y->first || std::abs(x->second - y->second) > tolerance * tolerance) return false;
  const BoundingBox ba = a.terminal.bounds(), bb = b.terminal.bounds();
  if ((ba.min - bb.min).norm() > tolerance || (ba.max - bb.max).norm() > tolerance) return false;
  const std::vector<CellKey> cells_a = surface_cells(a.terminal, 0.5 * tolerance), cells_b = surface_cells(b.terminal, 0.5 * tolerance);
  return cells_covered(cells_a, cells_b) && cells_covered(cells_b, cells_a);
}

}  // namespace dg
