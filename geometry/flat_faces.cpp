#include "geometry/flat_faces.h"

#include "geometry/fragment_merge.h"
#include "geometry/submesh.h"

#include <algorithm>
#include <map>
#include <numeric>

namespace dg {
namespace {

// Distance from a face's plane, relative to the mesh's bounding-box diagonal, within which a
// corner counts as lying in it. Text formats keep 6 or 7 significant digits, so the flat faces
// of real assets are flat only to about 1e-7 of their size; modelled detail is far larger.
constexpr double kFlatFraction = 1e-6;

}  // namespace

std::vector<std::uint32_t> flat_faces(const TriangleMesh& mesh, const std::vector<char>& kind, double tolerance) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> users;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) users[std::minmax(mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3])].push_back(t);
  std::vector<std::uint32_t> group(mesh.triangles.size());
  std::iota(group.begin(), group.end(), 0u);
  auto root = [&](std::uint32_t x) {
    while (group[x] != x) x = group[x] = group[group[x]];
    return x;
  };
  auto alike = [&](std::uint32_t a, std::uint32_t b) {
    return (kind.empty() || kind[a] == kind[b]) && (!mesh.has_materials() || mesh.materials[a] == mesh.materials[b]);
  };
  auto flat = [&](std::uint32_t a, std::uint32_t b) {  // b's corners on a's plane, same side up
    const Vec3 n = mesh.area_vector(a).normalized(), m = mesh.area_vector(b).normalized();
    if (!(n.dot(m) > 0.0)) return false;
    const Vec3& p = mesh.positions[mesh.triangles[a][0]];
    return std::all_of(mesh.triangles[b].begin(), mesh.triangles[b].end(),
                       [&](std::uint32_t v) { return std::abs(n.dot(mesh.positions[v] - p)) <= tolerance; });
  };
  for (const auto& [edge, triangles] : users)
    if (triangles.size() == 2 && alike(triangles[0], triangles[1]) && flat(triangles[0], triangles[1]) &&
        flat(triangles[1], triangles[0]))
      group[root(triangles[0])] = root(triangles[1]);
  for (std::uint32_t t = 0; t < group.size(); ++t) group[t] = root(t);
  return group;
}

TriangleMesh merge_flat_faces(const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) return mesh;
  Eigen::AlignedBox3d bounds;
  for (const Vec3& p : mesh.positions) bounds.extend(p);
  const double tolerance = kFlatFraction * bounds.diagonal().norm();
  const std::vector<std::uint32_t> face = flat_faces(mesh, {}, tolerance);
  const std::vector<std::uint32_t> one_label(mesh.triangles.size(), 0);
  const std::vector<char> pinned(mesh.positions.size(), 0);
  MergedFragments merged = merge_fragments(mesh, face, one_label, pinned, {.straighten_label_borders = true, .moved_distance = tolerance});
  return without_unused_vertices(merged.mesh);
}

}  // namespace dg
