#include "geometry/t_junctions.h"

#include "geometry/slab_cut.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace dg {
namespace {

using EdgeKey = std::pair<std::uint32_t, std::uint32_t>;

// Boundary edges (used by one triangle) with the triangle and the corner where the edge starts,
// sorted by edge.
// With `only`, just the edges whose two ends are flagged (their other uses are edges of the
// same kind, so the counts stay right).
std::vector<std::pair<EdgeKey, std::pair<std::size_t, int>>> boundary_edges(const TriangleMesh& mesh, const std::vector<char>* only) {
  std::vector<std::pair<EdgeKey, std::pair<std::size_t, int>>> uses;
  uses.reserve(only ? 0 : 3 * mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      if (only && !((*only)[a] && (*only)[b])) continue;
      uses.push_back({std::minmax(a, b), {t, k}});
    }
  std::sort(uses.begin(), uses.end());
  std::vector<std::pair<EdgeKey, std::pair<std::size_t, int>>> single;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].first == uses[i].first) ++j;
    if (j - i == 1) single.push_back(uses[i]);
    i = j;
  }
  return single;
}

}  // namespace

std::size_t resolve_t_junctions(TriangleMesh& mesh, double tolerance, const std::vector<char>* seam_vertices) {
  std::vector<char> seam;
  const std::vector<std::uint32_t> remap = weld_vertices(mesh, tolerance, seam_vertices);
  if (seam_vertices) {
    seam.assign(mesh.positions.size(), 0);
    for (std::size_t v = 0; v < remap.size(); ++v)
      if ((*seam_vertices)[v]) seam[remap[v]] = 1;
  }
  const std::vector<char>* only = seam_vertices ? &seam : nullptr;
  std::size_t splits = 0;
  for (int pass = 0; pass < 4; ++pass) {
    const auto edges = boundary_edges(mesh, only);
    if (edges.empty()) break;
    // Boundary vertices in a spatial hash with cells about as long as a boundary edge.
    double edge_length = 0.0;
    for (const auto& [edge, use] : edges) edge_length += (mesh.positions[edge.first] - mesh.positions[edge.second]).norm();
    edge_length /= static_cast<double>(edges.size());
    const double cell = std::max({tolerance * 16.0, edge_length, 1e-300});
    auto key = [&](const Vec3& p) {
      return std::array<std::int64_t, 3>{static_cast<std::int64_t>(std::floor(p.x() / cell)),
                                         static_cast<std::int64_t>(std::floor(p.y() / cell)),
                                         static_cast<std::int64_t>(std::floor(p.z() / cell))};
    };
    std::map<std::array<std::int64_t, 3>, std::vector<std::uint32_t>> buckets;
    std::vector<char> on_boundary(mesh.positions.size(), 0);
    for (const auto& [edge, use] : edges) on_boundary[edge.first] = on_boundary[edge.second] = 1;
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v)
      if (on_boundary[v]) buckets[key(mesh.positions[v])].push_back(v);

    std::vector<bool> replaced(mesh.triangles.size(), false);
    std::vector<Triangle> added;
    for (const auto& [edge, use] : edges) {
      const auto [t, k] = use;
      if (replaced[t]) continue;  // one split per triangle and pass
      const Triangle tri = mesh.triangles[t];
      const std::uint32_t a = tri[k], b = tri[(k + 1) % 3], c = tri[(k + 2) % 3];
      const Vec3 pa = mesh.positions[a], pb = mesh.positions[b];
      const Vec3 ab = pb - pa;
      const double length2 = ab.squaredNorm();
      if (length2 <= 0.0) continue;
      // Vertices on the open segment, ordered from a to b.
      std::vector<std::pair<double, std::uint32_t>> inner;
      const auto lo = key(pa.cwiseMin(pb) - Vec3::Constant(tolerance)), hi = key(pa.cwiseMax(pb) + Vec3::Constant(tolerance));
      if ((hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1) > 512) {
        // Long edge: scan all boundary vertices instead of many empty cells.
        for (const auto& [cell_key, vertices] : buckets)
          for (std::uint32_t v : vertices) {
            const double s = (mesh.positions[v] - pa).dot(ab) / length2;
            if (v != a && v != b && s > 0.0 && s < 1.0 && (pa + s * ab - mesh.positions[v]).norm() <= tolerance)
              inner.emplace_back(s, v);
          }
      } else {
        for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
          for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
            for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
              const auto found = buckets.find({x, y, z});
              if (found == buckets.end()) continue;
              for (std::uint32_t v : found->second) {
                const double s = (mesh.positions[v] - pa).dot(ab) / length2;
                if (v != a && v != b && s > 0.0 && s < 1.0 && (pa + s * ab - mesh.positions[v]).norm() <= tolerance)
                  inner.emplace_back(s, v);
              }
            }
      }
      if (inner.empty()) continue;
      std::sort(inner.begin(), inner.end());
      replaced[t] = true;
      std::uint32_t previous = a;
      for (const auto& [s, v] : inner) {
        added.push_back({previous, v, c});
        previous = v;
      }
      added.push_back({previous, b, c});
      splits += inner.size();
    }
    if (added.empty()) break;
    std::vector<Triangle> kept;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      if (!replaced[t]) kept.push_back(mesh.triangles[t]);
    kept.insert(kept.end(), added.begin(), added.end());
    mesh.triangles = std::move(kept);
  }
  return splits;
}

}  // namespace dg
