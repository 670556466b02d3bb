#include "geometry/vertex_weld.h"

#include "geometry/cell_key.h"
#include "geometry/slab_cut.h"

#include <algorithm>
#include <unordered_map>

namespace dg {
namespace {

constexpr std::uint32_t kEnd = std::numeric_limits<std::uint32_t>::max();

// Applies `remap` (old vertex -> kept vertex) to the triangles, keeps `kept` as the positions and
// drops the triangles that became degenerate.
void apply_remap(TriangleMesh& mesh, const std::vector<std::uint32_t>& remap, std::vector<Vec3> kept) {
  for (Triangle& tri : mesh.triangles)
    for (std::uint32_t& v : tri) v = remap[v];
  mesh.positions = std::move(kept);
  drop_repeated_corners(mesh);
}

// Unlabelled weld: each vertex merges into the first kept vertex within `tolerance` found in the
// cells around it.
std::vector<std::uint32_t> weld_first(TriangleMesh& mesh, double tolerance) {
  const double cell = std::max(tolerance, 1e-300) * 4.0;
  // Kept vertices per grid cell as intrusive lists: bucket head, then `next` per kept vertex.
  std::unordered_map<CellKey, std::uint32_t, CellKeyHash> head;
  head.reserve(mesh.positions.size());
  std::vector<std::uint32_t> next;
  std::vector<std::uint32_t> remap(mesh.positions.size());
  std::vector<Vec3> kept;
  kept.reserve(mesh.positions.size());
  next.reserve(mesh.positions.size());
  for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3& p = mesh.positions[v];
    const CellKey k = cell_key(p, cell);
    std::uint32_t found = kEnd;
    for (std::int64_t dx = -1; dx <= 1 && found == kEnd; ++dx)
      for (std::int64_t dy = -1; dy <= 1 && found == kEnd; ++dy)
        for (std::int64_t dz = -1; dz <= 1 && found == kEnd; ++dz) {
          const auto bucket = head.find({k[0] + dx, k[1] + dy, k[2] + dz});
          if (bucket == head.end()) continue;
          for (std::uint32_t w = bucket->second; w != kEnd; w = next[w])
            if ((kept[w] - p).norm() <= tolerance) {
              found = w;
              break;
            }
        }
    if (found == kEnd) {
      found = static_cast<std::uint32_t>(kept.size());
      kept.push_back(p);
      const auto [bucket, inserted] = head.try_emplace(k, found);
      next.push_back(inserted ? kEnd : bucket->second);
      bucket->second = found;
    }
    remap[v] = found;
  }
  apply_remap(mesh, remap, std::move(kept));
  return remap;
}

// Labelled weld: each labelled vertex, in index order, joins the nearest kept vertex within
// `tolerance` whose surface does not face away from its own and that no vertex of its copy
// joined but its seam neighbour (or one within `same_copy_tolerance`).
std::vector<std::uint32_t> weld_copies(TriangleMesh& mesh, double tolerance, const std::vector<std::uint32_t>& copies,
                                       double same_copy_tolerance) {
  const double cell = std::max(tolerance, 1e-300) * 4.0;
  // Kept labelled vertices per grid cell as intrusive lists, and the old vertices each kept one
  // stands for (the first is itself).
  std::unordered_map<CellKey, std::uint32_t, CellKeyHash> head;
  std::vector<std::uint32_t> next, first_member;
  std::vector<std::uint32_t> next_member(mesh.positions.size(), kEnd);
  std::vector<std::uint32_t> remap(mesh.positions.size());
  std::vector<Vec3> kept;
  // The normal of each vertex's surface, and of the vertex each kept one was first: touching
  // parts face away from each other (a leg's top against a seat's underside), and the seams of
  // both, cut along one line, lie at one spot.
  const std::vector<Vec3> normals = vertex_normals(mesh);
  std::vector<Vec3> kept_normals;
  // Open edges of the copies (used by one triangle, both ends labelled): their seam edges.
  auto edge_key = [](std::uint32_t a, std::uint32_t b) { return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b); };
  std::unordered_map<std::uint64_t, int> seam_edge_uses;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (copies[t[k]] != kNotOnSeam && copies[t[(k + 1) % 3]] != kNotOnSeam) ++seam_edge_uses[edge_key(t[k], t[(k + 1) % 3])];
  auto seam_edge = [&](std::uint32_t a, std::uint32_t b) {
    const auto found = seam_edge_uses.find(edge_key(a, b));
    return found != seam_edge_uses.end() && found->second == 1;
  };
  // Whether a vertex of v's copy joined w, unless one did that is v's neighbour along the copy's
  // seam: a seam edge shorter than the tolerance whose ends both lie nearest to w collapses
  // (a cut leaves such edges; kept, the second end would fold back across the first).
  auto holds_copy = [&](std::uint32_t w, std::uint32_t v) {
    bool holds = false;
    for (std::uint32_t u = first_member[w]; u != kEnd; u = next_member[u]) {
      if (copies[u] != copies[v]) continue;
      if (seam_edge(u, v)) return false;
      holds = true;
    }
    return holds;
  };
  for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3& p = mesh.positions[v];
    const CellKey k = cell_key(p, cell);
    std::uint32_t found = kEnd;
    if (copies[v] != kNotOnSeam) {
      double nearest = tolerance;
      for (std::int64_t dx = -1; dx <= 1; ++dx)
        for (std::int64_t dy = -1; dy <= 1; ++dy)
          for (std::int64_t dz = -1; dz <= 1; ++dz) {
            const auto bucket = head.find({k[0] + dx, k[1] + dy, k[2] + dz});
            if (bucket == head.end()) continue;
            for (std::uint32_t w = bucket->second; w != kEnd; w = next[w]) {
              const double distance = (kept[w] - p).norm();
              if (distance <= nearest && (distance < nearest || w < found) && kept_normals[w].dot(normals[v]) >= 0.0 &&
                  (distance <= same_copy_tolerance || !holds_copy(w, v))) {
                found = w;
                nearest = distance;
              }
            }
          }
    }
    if (found == kEnd) {
      found = static_cast<std::uint32_t>(kept.size());
      kept.push_back(p);
      kept_normals.push_back(normals[v]);
      next.push_back(kEnd);
      first_member.push_back(kEnd);
      if (copies[v] != kNotOnSeam) {  // unlabelled vertices are never joined
        const auto [bucket, inserted] = head.try_emplace(k, found);
        if (!inserted) next.back() = bucket->second, bucket->second = found;
      }
    }
    next_member[v] = first_member[found];
    first_member[found] = v;
    remap[v] = found;
  }
  apply_remap(mesh, remap, std::move(kept));
  return remap;
}

}  // namespace

std::vector<std::uint32_t> weld_vertices(TriangleMesh& mesh, double tolerance, const std::vector<std::uint32_t>* copies,
                                         double same_copy_tolerance) {
  return copies ? weld_copies(mesh, tolerance, *copies, same_copy_tolerance) : weld_first(mesh, tolerance);
}

}  // namespace dg
