#include "geometry/same_surface.h"

#include "geometry/cell_key.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <tuple>

namespace dg {
namespace {

// The cells (cubes of edge `cell`, model units) that points of the listed triangles of `mesh`
// fall in, sampled on each triangle in rows parallel to its longest edge, at most one cell apart
// along and across them (so a sliver costs as few samples as its area needs; a cell the surface
// only clips may be missed, but a neighbour of it is not); sorted, without repeats.
std::vector<CellKey> surface_cells(const TriangleMesh& mesh, const std::vector<std::size_t>& triangles, double cell) {
  std::vector<CellKey> cells;
  auto add = [&](const Vec3& p) { cells.push_back(cell_key(p, cell)); };
  auto compact = [&] {
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  };
  std::size_t compact_at = 4096;
  for (std::size_t t : triangles) {
    auto [a, b, c] = mesh.corners(t);
    // Make a-b the longest edge.
    if ((c - b).norm() > (b - a).norm() && (c - b).norm() >= (a - c).norm()) std::tie(a, b, c) = std::tuple{b, c, a};
    else if ((a - c).norm() > (b - a).norm()) std::tie(a, b, c) = std::tuple{c, a, b};
    const double length = (b - a).norm();
    const double height = length > 0.0 ? (b - a).cross(c - a).norm() / length : (c - a).norm();
    const int rows = std::max(1, static_cast<int>(std::ceil(height / cell)));
    for (int k = 0; k <= rows; ++k) {
      const double s = static_cast<double>(k) / rows;  // row from a-b (s = 0) to c (s = 1)
      const Vec3 from = a + s * (c - a), to = b + s * (c - b);
      const int steps = std::max(1, static_cast<int>(std::ceil((1.0 - s) * length / cell)));
      for (int i = 0; i <= steps; ++i) add(from + (static_cast<double>(i) / steps) * (to - from));
    }
    // Many samples fall in one cell: repeats go whenever the list doubles, so memory follows the
    // cells, not the samples.
    if (cells.size() >= compact_at) {
      compact();
      compact_at = 2 * cells.size() + 4096;
    }
  }
  compact();
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

// The triangles of `mesh` per material index (one entry for a mesh without materials), with
// their area (model units^2).
struct MaterialPart {
  std::vector<std::size_t> triangles;
  double area = 0.0;
};
std::map<std::uint32_t, MaterialPart> parts_by_material(const TriangleMesh& mesh) {
  std::map<std::uint32_t, MaterialPart> parts;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    MaterialPart& part = parts[mesh.has_materials() ? mesh.materials[t] : 0];
    part.triangles.push_back(t);
    part.area += 0.5 * mesh.area_vector(t).norm();
  }
  return parts;
}

}  // namespace

bool same_surface(const TriangleMesh& a, const TriangleMesh& b, double tolerance) {
  const BoundingBox ba = a.bounds(), bb = b.bounds();
  if ((ba.min - bb.min).norm() > tolerance || (ba.max - bb.max).norm() > tolerance) return false;
  // Each material's surface covers the other's; a material with no more than tolerance^2 of area
  // in one mesh may be missing from the other.
  const std::map<std::uint32_t, MaterialPart> parts_a = parts_by_material(a), parts_b = parts_by_material(b);
  const double negligible = tolerance * tolerance;
  auto matched = [&](const std::map<std::uint32_t, MaterialPart>& from, const std::map<std::uint32_t, MaterialPart>& to) {
    return std::all_of(from.begin(), from.end(), [&](const auto& entry) {
      return entry.second.area <= negligible || to.contains(entry.first);
    });
  };
  if (!matched(parts_a, parts_b) || !matched(parts_b, parts_a)) return false;
  for (const auto& [material, part_a] : parts_a) {
    const auto found = parts_b.find(material);
    if (found == parts_b.end()) continue;
    const std::vector<CellKey> cells_a = surface_cells(a, part_a.triangles, 0.5 * tolerance),
                               cells_b = surface_cells(b, found->second.triangles, 0.5 * tolerance);
    if (!cells_covered(cells_a, cells_b) || !cells_covered(cells_b, cells_a)) return false;
  }
  return true;
}

bool same_points(const PointCloud& a, const PointCloud& b, double tolerance) {
  if (a.positions.empty() || b.positions.empty()) return a.positions.empty() == b.positions.empty();
  const BoundingBox ba = a.bounds(), bb = b.bounds();
  if ((ba.min - bb.min).norm() > 2.0 * tolerance || (ba.max - bb.max).norm() > 2.0 * tolerance) return false;
  auto cells_of = [&](const PointCloud& cloud) {
    std::vector<CellKey> cells;
    for (const Vec3& p : cloud.positions) cells.push_back(cell_key(p, tolerance));
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    return cells;
  };
  const std::vector<CellKey> cells_a = cells_of(a), cells_b = cells_of(b);
  return cells_covered(cells_a, cells_b) && cells_covered(cells_b, cells_a);
}

}  // namespace dg
