#include "geometry/flat_faces.h"

#include "geometry/fragment_merge.h"
#include "geometry/submesh.h"
#include "geometry/topology.h"

#include <algorithm>
#include <numeric>

namespace dg {

std::vector<std::uint32_t> flat_faces(const TriangleMesh& mesh, const std::vector<char>& kind, double tolerance) {
  const auto count = static_cast<std::uint32_t>(mesh.triangles.size());
  std::vector<Vec3> normal(count);
  for (std::uint32_t t = 0; t < count; ++t) normal[t] = mesh.area_vector(t).normalized();
  const VertexTriangles around = vertex_triangles(mesh);
  std::vector<std::uint32_t> group(count);
  std::iota(group.begin(), group.end(), 0u);
  auto root = [&](std::uint32_t x) {
    while (group[x] != x) x = group[x] = group[group[x]];
    return x;
  };
  auto alike = [&](std::uint32_t a, std::uint32_t b) {
    return (kind.empty() || kind[a] == kind[b]) && (!mesh.has_materials() || mesh.materials[a] == mesh.materials[b]);
  };
  auto flat = [&](std::uint32_t a, std::uint32_t b) {  // b's corners on a's plane, same side up
    if (!(normal[a].dot(normal[b]) > 0.0)) return false;
    const Vec3& p = mesh.positions[mesh.triangles[a][0]];
    return std::all_of(mesh.triangles[b].begin(), mesh.triangles[b].end(),
                       [&](std::uint32_t v) { return std::abs(normal[a].dot(mesh.positions[v] - p)) <= tolerance; });
  };
  auto joins = [&](std::uint32_t a, std::uint32_t b) { return a != b && alike(a, b) && flat(a, b) && flat(b, a); };
  std::vector<std::uint32_t> users;
  for (std::uint32_t t = 0; t < count; ++t)
    for (int k = 0; k < 3; ++k) {
      // The triangles on edge (a, b): those around a that have b.
      const std::uint32_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      users.clear();
      for (std::uint32_t i = around.first[a]; i < around.first[a + 1]; ++i) {
        const std::uint32_t u = around.triangles[i];
        if (std::find(mesh.triangles[u].begin(), mesh.triangles[u].end(), b) != mesh.triangles[u].end()) users.push_back(u);
      }
      // Joined with the one other user it lies flat with, when that one lies flat with no third:
      // the two sides of a double-sided face (four users) each stay one face.
      auto partners = [&](std::uint32_t x) {
        return std::count_if(users.begin(), users.end(), [&](std::uint32_t u) { return joins(x, u); });
      };
      for (std::uint32_t other : users)
        if (other > t && joins(t, other) && (users.size() == 2 || (partners(t) == 1 && partners(other) == 1)))
          group[root(t)] = root(other);
    }
  for (std::uint32_t t = 0; t < count; ++t) group[t] = root(t);
  return group;
}

TriangleMesh merge_flat_faces(const TriangleMesh& mesh, const FlatFaceMergeOptions& options) {
  if (mesh.triangles.empty()) return mesh;
  const double tolerance = kFlatFraction * mesh.bounds().diagonal();
  const std::vector<std::uint32_t> face = flat_faces(mesh, {}, tolerance);
  const std::vector<std::uint32_t> one_label(mesh.triangles.size(), 0);
  const std::vector<char> pinned(mesh.positions.size(), 0);
  const MergedFragments merged = merge_fragments(mesh, face, one_label, pinned,
                                                 {.straighten_open_borders = options.straighten_open_borders,
                                                  .straighten_label_borders = true,
                                                  .moved_distance = std::max(tolerance, options.moved_distance)});
  return without_unused_vertices(merged.mesh);
}

}  // namespace dg
