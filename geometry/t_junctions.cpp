#include "geometry/t_junctions.h"

#include "geometry/cell_key.h"
#include "geometry/slab_cut.h"
#include "geometry/topology.h"
#include "geometry/vertex_weld.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <tuple>
#include <unordered_map>

namespace dg {
namespace {

using EdgeKey = std::pair<std::uint32_t, std::uint32_t>;

// A use of an undirected edge: the edge, then the triangle and the corner where it starts.
struct EdgeUse {
  EdgeKey edge;
  std::uint32_t triangle = 0;
  int corner = 0;
};

// Boundary edges (used by one triangle) among the edges of `triangles`, sorted by edge.
// With `only`, just the edges whose two ends are flagged; every triangle using such an edge
// must then be listed (it has two flagged corners), so the counts stay right.
std::vector<EdgeUse> boundary_edges(const TriangleMesh& mesh, const std::vector<std::uint32_t>& triangles,
                                    const std::vector<char>* only) {
  std::vector<EdgeUse> uses;
  uses.reserve(3 * triangles.size());
  for (std::uint32_t t : triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      if (only && !((*only)[a] && (*only)[b])) continue;
      uses.push_back({std::minmax(a, b), t, k});
    }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return std::tie(x.edge, x.triangle, x.corner) < std::tie(y.edge, y.triangle, y.corner);
  });
  std::vector<EdgeUse> single;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].edge == uses[i].edge) ++j;
    if (j - i == 1) single.push_back(uses[i]);
    i = j;
  }
  return single;
}

// Triangles with at least two flagged corners (all triangles without flags): the only ones
// that can hold an edge between two flagged vertices.
std::vector<std::uint32_t> seam_triangles(const TriangleMesh& mesh, const std::vector<char>* only) {
  std::vector<std::uint32_t> triangles;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    if (!only || (*only)[tri[0]] + (*only)[tri[1]] + (*only)[tri[2]] >= 2) triangles.push_back(t);
  }
  return triangles;
}

// The ends of boundary edges in a spatial hash with cells at least `cell` wide.
class BoundaryVertexGrid {
 public:
  BoundaryVertexGrid(const TriangleMesh& mesh, const std::vector<EdgeUse>& edges, double cell) : cell_(cell) {
    for (const EdgeUse& use : edges)
      for (std::uint32_t v : {use.edge.first, use.edge.second}) vertices_.push_back(v);
    std::sort(vertices_.begin(), vertices_.end());
    vertices_.erase(std::unique(vertices_.begin(), vertices_.end()), vertices_.end());
    for (std::uint32_t v : vertices_) buckets_[key(mesh.positions[v])].push_back(v);
  }

  CellKey key(const Vec3& p) const { return cell_key(p, cell_); }

  // Calls visit(v) for every boundary vertex v in the cells overlapping the box [lo, hi]
  // (or for all of them when that box spans more cells than there are vertices).
  template <class Visit>
  void for_each_near(const Vec3& lo, const Vec3& hi, Visit&& visit) const {
    const CellKey a = key(lo), b = key(hi);
    const double cells = static_cast<double>(b[0] - a[0] + 1) * static_cast<double>(b[1] - a[1] + 1) *
                         static_cast<double>(b[2] - a[2] + 1);
    if (cells > static_cast<double>(vertices_.size())) {
      for (std::uint32_t v : vertices_) visit(v);
      return;
    }
    for (std::int64_t x = a[0]; x <= b[0]; ++x)
      for (std::int64_t y = a[1]; y <= b[1]; ++y)
        for (std::int64_t z = a[2]; z <= b[2]; ++z) {
          const auto found = buckets_.find({x, y, z});
          if (found == buckets_.end()) continue;
          for (std::uint32_t v : found->second) visit(v);
        }
  }

 private:
  double cell_;
  std::vector<std::uint32_t> vertices_;
  std::unordered_map<CellKey, std::vector<std::uint32_t>, CellKeyHash> buckets_;
};

}  // namespace

std::vector<char> open_edge_vertices(const TriangleMesh& mesh) {
  std::vector<std::uint32_t> all(mesh.triangles.size());
  std::iota(all.begin(), all.end(), 0u);
  std::vector<char> open(mesh.positions.size(), 0);
  for (const EdgeUse& use : boundary_edges(mesh, all, nullptr)) open[use.edge.first] = open[use.edge.second] = 1;
  return open;
}

void append_seam_labels(std::vector<std::uint32_t>& labels, const std::vector<char>& open, std::uint32_t copy) {
  for (char on_seam : open) labels.push_back(on_seam ? copy : kNotOnSeam);
}

std::size_t resolve_t_junctions(TriangleMesh& mesh, double tolerance, const std::vector<std::uint32_t>* seam_copies,
                                double same_copy_tolerance) {
  // With labels, the copy of each triangle (of its seam corners), kept through the weld, which
  // drops the triangles whose corners merge.
  std::vector<std::uint32_t> triangle_copy;
  const std::vector<Triangle> unwelded = seam_copies ? mesh.triangles : std::vector<Triangle>{};
  const std::vector<std::uint32_t> remap = weld_vertices(mesh, tolerance, seam_copies, same_copy_tolerance);
  std::vector<char> seam;
  // With labels, the copies whose vertices each welded vertex joins.
  std::vector<std::vector<std::uint32_t>> copies_of;
  if (seam_copies) {
    seam.assign(mesh.positions.size(), 0);
    copies_of.resize(mesh.positions.size());
    for (std::size_t v = 0; v < remap.size(); ++v)
      if ((*seam_copies)[v] != kNotOnSeam) {
        seam[remap[v]] = 1;
        copies_of[remap[v]].push_back((*seam_copies)[v]);
      }
    for (const Triangle& tri : unwelded) {
      const std::uint32_t a = remap[tri[0]], b = remap[tri[1]], c = remap[tri[2]];
      if (a == b || b == c || c == a) continue;
      std::uint32_t copy = kNotOnSeam;
      for (std::uint32_t v : tri) copy = std::min(copy, (*seam_copies)[v]);
      triangle_copy.push_back(copy);
    }
  }
  const std::vector<char>* only = seam_copies ? &seam : nullptr;
  // A vertex of an edge's own copy farther from it than `same_copy_tolerance` lies on it within
  // that copy's piece: a touching part of the copy, which the edge does not meet in the piece
  // either, so it does not split the edge (a closer one closes a crack of the piece). Nor does a
  // vertex whose surface faces away from the edge's triangle, of any copy: a touching part cut
  // along the same line (a leg's top under a seat). Splits add no vertices, so the normals hold.
  const std::vector<Vec3> normals = seam_copies ? vertex_normals(mesh) : std::vector<Vec3>{};
  auto splits_edge = [&](std::uint32_t v, std::uint32_t triangle, double distance) {
    if (distance > tolerance) return false;
    if (!seam_copies) return true;
    if (normals[v].dot(mesh.area_vector(triangle)) < 0.0) return false;
    return distance <= same_copy_tolerance ||
           std::find(copies_of[v].begin(), copies_of[v].end(), triangle_copy[triangle]) == copies_of[v].end();
  };
  // Split triangles keep their index (the first part replaces them, the others are appended),
  // so the list of triangles that can hold seam edges only grows.
  std::vector<std::uint32_t> candidates = seam_triangles(mesh, only);
  std::size_t splits = 0;
  for (int pass = 0; pass < 4; ++pass) {
    const std::vector<EdgeUse> edges = boundary_edges(mesh, candidates, only);
    if (edges.empty()) break;
    // Cells about as long as a boundary edge.
    double edge_length = 0.0;
    for (const EdgeUse& use : edges) edge_length += (mesh.positions[use.edge.first] - mesh.positions[use.edge.second]).norm();
    edge_length /= static_cast<double>(edges.size());
    const BoundaryVertexGrid grid(mesh, edges, std::max({tolerance * 16.0, edge_length, 1e-300}));

    std::vector<char> replaced(mesh.triangles.size(), 0);
    std::vector<std::pair<std::uint32_t, Triangle>> first_parts;
    std::vector<std::pair<std::uint32_t, Triangle>> added;  // (source triangle, part)
    std::vector<std::pair<double, std::uint32_t>> inner;
    for (const EdgeUse& use : edges) {
      const std::uint32_t t = use.triangle;
      if (replaced[t]) continue;  // one split per triangle and pass
      const Triangle tri = mesh.triangles[t];
      const std::uint32_t a = tri[use.corner], b = tri[(use.corner + 1) % 3], c = tri[(use.corner + 2) % 3];
      const Vec3 pa = mesh.positions[a], pb = mesh.positions[b];
      const Vec3 ab = pb - pa;
      const double length2 = ab.squaredNorm();
      if (length2 <= 0.0) continue;
      // Boundary vertices on the open segment, ordered from a to b.
      inner.clear();
      grid.for_each_near(pa.cwiseMin(pb) - Vec3::Constant(tolerance), pa.cwiseMax(pb) + Vec3::Constant(tolerance),
                         [&](std::uint32_t v) {
                           const double s = (mesh.positions[v] - pa).dot(ab) / length2;
                           if (v != a && v != b && s > 0.0 && s < 1.0 && splits_edge(v, t, (pa + s * ab - mesh.positions[v]).norm()))
                             inner.emplace_back(s, v);
                         });
      if (inner.empty()) continue;
      std::sort(inner.begin(), inner.end());
      replaced[t] = 1;
      std::uint32_t previous = a;
      for (const auto& [s, v] : inner) {
        if (previous == a)
          first_parts.push_back({t, {a, v, c}});
        else
          added.push_back({t, {previous, v, c}});
        previous = v;
      }
      added.push_back({t, {previous, b, c}});
      splits += inner.size();
    }
    if (first_parts.empty()) break;
    for (const auto& [t, part] : first_parts) mesh.triangles[t] = part;
    const bool has_materials = mesh.has_materials();
    for (const auto& [source, part] : added) {
      candidates.push_back(static_cast<std::uint32_t>(mesh.triangles.size()));
      mesh.triangles.push_back(part);
      if (seam_copies) triangle_copy.push_back(triangle_copy[source]);
      if (has_materials) mesh.materials.push_back(mesh.materials[source]);
    }
  }
  // A sliver whose apex lies on its own open edge split into parts with a repeated corner: it had
  // no area, and its neighbours now meet along the edge it filled, so its parts go.
  drop_repeated_corners(mesh);
  return splits;
}

std::size_t drop_hanging_slivers(TriangleMesh& mesh, double tolerance) {
  const EdgeUsers edges = edge_users(mesh);
  // Triangles using the edge that starts at corner k of triangle t.
  auto users = [&](std::size_t t, int k) { return edges.group_end[3 * t + k] - edges.group_begin[3 * t + k]; };
  std::size_t dropped = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      if (users(t, k) < 3 || users(t, (k + 1) % 3) != 1 || users(t, (k + 2) % 3) != 1) continue;
      const Vec3 &pa = mesh.positions[tri[k]], &pb = mesh.positions[tri[(k + 1) % 3]];
      const Vec3& pc = mesh.positions[tri[(k + 2) % 3]];
      const Vec3 ab = pb - pa;
      const double s = std::clamp((pc - pa).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
      if ((pa + s * ab - pc).norm() > tolerance) continue;
      mesh.triangles[t] = {tri[0], tri[0], tri[0]};  // dropped below with the degenerate ones
      ++dropped;
      break;
    }
  }
  if (dropped > 0) drop_repeated_corners(mesh);
  return dropped;
}

std::size_t close_triangular_holes(TriangleMesh& mesh, double max_perimeter) {
  // Directed edges with how many triangles use them and one that does: an open edge is one only
  // one triangle uses and whose reverse none uses.
  struct EdgeUses {
    std::uint32_t count = 0, triangle = 0;
  };
  auto key = [](std::uint32_t a, std::uint32_t b) { return (static_cast<std::uint64_t>(a) << 32) | b; };
  std::unordered_map<std::uint64_t, EdgeUses> uses;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      EdgeUses& edge = uses[key(mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3])];
      if (edge.count++ == 0) edge.triangle = t;
    }
  auto open = [&](std::uint32_t a, std::uint32_t b) {
    const auto forward = uses.find(key(a, b));
    return forward != uses.end() && forward->second.count == 1 && !uses.contains(key(b, a));
  };
  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> next;  // open edges a -> b
  for (const auto& [e, edge] : uses) {
    const auto a = static_cast<std::uint32_t>(e >> 32), b = static_cast<std::uint32_t>(e & 0xFFFFFFFFu);
    if (open(a, b)) next[a].push_back(b);
  }
  std::vector<std::array<std::uint32_t, 3>> holes;  // open edges a -> b -> c -> a, a the smallest index
  for (const auto& [a, targets] : next)
    for (std::uint32_t b : targets) {
      const auto from_b = next.find(b);
      if (from_b == next.end()) continue;
      for (std::uint32_t c : from_b->second)
        if (a < b && a < c && open(c, a)) holes.push_back({a, b, c});
    }
  std::sort(holes.begin(), holes.end());
  const bool has_materials = mesh.has_materials();
  std::size_t closed = 0;
  for (const auto& [a, b, c] : holes) {
    const Vec3 &pa = mesh.positions[a], &pb = mesh.positions[b], &pc = mesh.positions[c];
    if ((pb - pa).norm() + (pc - pb).norm() + (pa - pc).norm() > max_perimeter) continue;
    if (has_materials) mesh.materials.push_back(mesh.materials[uses.at(key(a, b)).triangle]);
    mesh.triangles.push_back({b, a, c});  // uses b -> a, a -> c, c -> b: the open edges reversed
    ++closed;
  }
  return closed;
}

}  // namespace dg
