#include "geometry/fragment_merge.h"

#include "geometry/cleaning.h"
#include "geometry/topology.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <map>
#include <numeric>
#include <unordered_map>

namespace dg {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Kernel>;  // mesh vertex
using FaceInfo = CGAL::Triangulation_face_base_with_info_2<int, Kernel>;                 // nesting level, -1 = unknown
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel, FaceInfo>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>,
                                                       CGAL::Exact_predicates_tag>;

// |Cosine| between unit normals above which a triangle lies parallel to a region (about 0.1
// degree): its back face, or another layer of a face a messy mesh holds twice.
constexpr double kParallel = 1.0 - 1e-6;

std::uint64_t key_of(std::uint32_t a, std::uint32_t b) {
  const auto [lo, hi] = std::minmax(a, b);
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// Nesting level of every face: 0 outside, +1 across each constrained edge.
void mark_nesting(Cdt& cdt) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::deque<std::pair<Cdt::Face_handle, int>> seeds{{cdt.infinite_face(), 0}};
  while (!seeds.empty()) {
    const auto [seed, level] = seeds.front();
    seeds.pop_front();
    if (seed->info() != -1) continue;
    std::deque<Cdt::Face_handle> queue{seed};
    seed->info() = level;
    while (!queue.empty()) {
      const Cdt::Face_handle f = queue.front();
      queue.pop_front();
      for (int i = 0; i < 3; ++i) {
        const Cdt::Face_handle n = f->neighbor(i);
        if (n->info() != -1) continue;
        if (cdt.is_constrained({f, i})) {
          seeds.push_back({n, level + 1});
        } else {
          n->info() = level;
          queue.push_back(n);
        }
      }
    }
  }
}

// True when vertex v lies strictly between vertices a and b on the segment joining them
// (within 1e-9 of its length).
bool on_segment(const std::vector<Vec3>& positions, std::uint32_t v, std::uint32_t a, std::uint32_t b) {
  const Vec3 &p = positions[v], &pa = positions[a], &pb = positions[b];
  const double length = (pb - pa).norm();
  return length > 0.0 && (pb - pa).cross(p - pa).norm() <= 1e-9 * length * length && (p - pa).dot(pb - pa) > 0.0 &&
         (p - pb).dot(pa - pb) > 0.0;
}

double area_of(const std::vector<Vec3>& positions, const Triangle& t) {
  return 0.5 * (positions[t[1]] - positions[t[0]]).cross(positions[t[2]] - positions[t[0]]).norm();
}

// Re-triangulates one region (triangles of `mesh`) keeping the flagged vertices of its border;
// false (nothing added) when the result would not cover the region exactly, or when one of its
// new edges (inside it, or a straightened piece of its border) is an edge of a triangle of
// another region that does not lie in the same plane (`elsewhere(a, b, normal)`,
// `normal` the region's unit normal): a messy mesh can have a part touching a face along a line
// the face's own triangles do not follow, and the new edge would join that part's edge into a
// non-manifold one. A face in the same plane may share it: the back face of a double-sided
// face, or another layer of a face the mesh holds twice (the house of the corpus has walls
// drawn twice, triangulated along other diagonals; the two layers share the cuts' vertices).
template <typename EdgeTest>
bool retriangulate(const TriangleMesh& mesh, const std::vector<std::uint32_t>& region, const std::vector<char>& interior_edge,
                   const std::vector<char>& kept, double moved_distance, const EdgeTest& elsewhere, std::vector<Triangle>& out) {
  const std::vector<Vec3>& positions = mesh.positions;
  Vec3 normal = Vec3::Zero();
  double area = 0.0, border_length = 0.0;
  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> next;  // border: vertex -> following vertices
  for (std::uint32_t t : region) {
    const Triangle& tri = mesh.triangles[t];
    normal += (positions[tri[1]] - positions[tri[0]]).cross(positions[tri[2]] - positions[tri[0]]);
    area += area_of(positions, tri);
    for (int k = 0; k < 3; ++k)
      if (!interior_edge[3 * static_cast<std::size_t>(t) + k]) {
        next[tri[k]].push_back(tri[(k + 1) % 3]);
        border_length += (positions[tri[(k + 1) % 3]] - positions[tri[k]]).norm();
      }
  }
  if (!(normal.norm() > 0.0)) return false;
  normal.normalize();
  const Vec3 u = normal.unitOrthogonal(), w = normal.cross(u);
  Cdt cdt;
  std::unordered_map<std::uint32_t, Cdt::Vertex_handle> handle;
  std::vector<std::uint32_t> starts;
  for (const auto& [v, following] : next)
    if (kept[v]) starts.push_back(v);
  std::sort(starts.begin(), starts.end());  // insertion order fixed: same result every run
  for (std::uint32_t v : starts) {
    const Vec3& p = positions[v];
    const std::size_t before = cdt.number_of_vertices();
    const Cdt::Vertex_handle h = cdt.insert(Kernel::Point_2(p.dot(u), p.dot(w)));
    if (cdt.number_of_vertices() == before) return false;  // two border vertices at one spot
    h->info() = v;
    handle.emplace(v, h);
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> outline;  // the straightened border, directed
  std::size_t steps = 0, border_edges = 0;
  for (const auto& [v, following] : next) border_edges += following.size();
  for (std::uint32_t v : starts)
    for (std::uint32_t to : next[v]) {
      const bool straightened = !kept[to];
      while (!kept[to]) {  // a vertex only on a straight border: walk on to the next kept one
        const auto found = next.find(to);
        if (found == next.end() || found->second.size() != 1 || ++steps > border_edges) return false;
        to = found->second.front();
      }
      if (straightened && elsewhere(v, to, normal)) return false;
      const auto end = handle.find(to);
      if (end == handle.end()) return false;  // the border does not close
      if (to == v) return false;  // a loop with one kept vertex: no edge to constrain
      cdt.insert_constraint(handle.at(v), end->second);
      outline.emplace_back(v, to);
      if (cdt.number_of_vertices() != starts.size()) return false;  // constraints crossed
    }
  mark_nesting(cdt);
  std::vector<Triangle> triangles;
  double covered = 0.0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info() % 2 == 0) continue;
    Triangle t;
    for (int k = 0; k < 3; ++k) t[k] = f->vertex(k)->info();
    for (int k = 0; k < 3; ++k)  // edge k lies opposite corner k
      if (!cdt.is_constrained({f, k}) && elsewhere(t[(k + 1) % 3], t[(k + 2) % 3], normal)) return false;
    if (nearly_collinear(positions[t[0]], positions[t[1]], positions[t[2]])) return false;  // cleaning would drop it
    covered += area_of(positions, t);
    triangles.push_back(t);
  }
  // Dropping a border vertex that cutting moved off its straight border by up to
  // moved_distance changes the area by at most that times half its two border edges.
  if (std::abs(covered - area) > 1e-9 * area + moved_distance * border_length) return false;
  // Every piece of the outline with the region on one side only (not a slit or a fin's foot,
  // walked both ways) must stay a border edge of the new triangles: a region whose border touches
  // itself (a crack ending inside a messy face) can fill the right area with another border.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> directed;
  for (const Triangle& t : triangles)
    for (int k = 0; k < 3; ++k) directed.emplace_back(t[k], t[(k + 1) % 3]);
  std::sort(directed.begin(), directed.end());
  std::sort(outline.begin(), outline.end());
  auto in = [](const auto& edges, std::uint32_t a, std::uint32_t b) { return std::binary_search(edges.begin(), edges.end(), std::pair{a, b}); };
  for (const auto& [a, b] : outline)
    if (!in(outline, b, a) && (!in(directed, a, b) || in(directed, b, a))) return false;
  out.insert(out.end(), triangles.begin(), triangles.end());
  return true;
}

// Per region: the first region whose fragments are the same triangles (vertex sets, either
// orientation), itself when no earlier one is. A face that a messy mesh holds twice is cut alike
// in both copies; each copy's new edges would be edges of the other's fragments, so the two are
// re-triangulated as one.
std::vector<std::uint32_t> twin_leaders(const TriangleMesh& mesh, const std::vector<std::vector<std::uint32_t>>& regions) {
  std::map<std::vector<Triangle>, std::uint32_t> first;
  std::vector<std::uint32_t> leader(regions.size());
  for (std::uint32_t r = 0; r < regions.size(); ++r) {
    leader[r] = r;
    if (regions[r].size() < 2) continue;
    std::vector<Triangle> signature;
    for (std::uint32_t t : regions[r]) {
      Triangle sorted = mesh.triangles[t];
      std::sort(sorted.begin(), sorted.end());
      signature.push_back(sorted);
    }
    std::sort(signature.begin(), signature.end());
    leader[r] = first.emplace(std::move(signature), r).first->second;
  }
  return leader;
}

}  // namespace

MergedFragments merge_fragments(const TriangleMesh& mesh, const std::vector<std::uint32_t>& origin,
                                const std::vector<std::uint32_t>& label, const std::vector<char>& pinned,
                                const FragmentMergeOptions& options) {
  const bool straighten_open_borders = options.straighten_open_borders;
  const bool straighten_label_borders = options.straighten_label_borders;
  const auto triangle_count = static_cast<std::uint32_t>(mesh.triangles.size());
  std::vector<std::pair<std::uint64_t, std::uint32_t>> uses;  // edge key, corner 3t+k
  uses.reserve(3 * static_cast<std::size_t>(triangle_count));
  for (std::uint32_t t = 0; t < triangle_count; ++t)
    for (std::uint32_t k = 0; k < 3; ++k) uses.push_back({key_of(mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3]), 3 * t + k});
  std::sort(uses.begin(), uses.end());
  std::vector<char> kept = pinned, interior_edge(uses.size(), 0);
  std::vector<std::uint32_t> parent(triangle_count);
  std::iota(parent.begin(), parent.end(), 0u);
  // Triangles of different materials never share a region: their border is a label border.
  const bool has_materials = mesh.has_materials();
  auto same_label = [&](std::uint32_t a, std::uint32_t b) {
    return label[a] == label[b] && (!has_materials || mesh.materials[a] == mesh.materials[b]);
  };
  // Vertices on open edges that may go: two open edges in a straight line, nothing else but
  // joined edges around (the vertex's other end of each open edge is recorded).
  std::vector<std::array<std::uint32_t, 2>> open_ends(straighten_open_borders ? mesh.positions.size() : 0);
  std::vector<std::uint8_t> open_count(open_ends.size(), 0);
  std::vector<char> between_origins(open_ends.size(), 0);  // on an edge between two input triangles
  // Where region borders (edges between labels or origins) meet: the other ends of a vertex's
  // first two border edges, and how many end there (a third one keeps the vertex).
  std::vector<std::array<std::uint32_t, 2>> border_ends(straighten_label_borders ? mesh.positions.size() : 0);
  std::vector<std::uint8_t> border_count(border_ends.size(), 0);
  // An edge inside a face the mesh holds twice or more, in layers (copies cut alike, or drawn
  // along other diagonals, sharing the cuts' vertices): all its users lie in one plane and pair
  // up two per input triangle, perhaps leaving two users of two input triangles. Each such pair
  // is joined across it as if the other layers were not there, and only the users left count
  // below. `users`: the corners 3t + k of the edge's users that count.
  std::vector<std::uint32_t> users, left;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> joined;
  auto set_aside_layers = [&](std::size_t first, std::size_t end) {
    users.clear();
    for (std::size_t u = first; u < end; ++u) users.push_back(uses[u].second);
    if (users.size() < 3) return;
    const Vec3 normal = mesh.area_vector(users.front() / 3).normalized();
    for (std::uint32_t c : users)
      if (!(std::abs(mesh.area_vector(c / 3).normalized().dot(normal)) > kParallel)) return;
    std::vector<std::uint32_t> by_origin = users;
    std::sort(by_origin.begin(), by_origin.end(), [&](std::uint32_t x, std::uint32_t y) {
      return std::pair{origin[x / 3], x} < std::pair{origin[y / 3], y};
    });
    left.clear();
    joined.clear();
    for (std::size_t p = 0; p < by_origin.size();) {
      std::size_t q = p;
      while (q < by_origin.size() && origin[by_origin[q] / 3] == origin[by_origin[p] / 3]) ++q;
      if (q - p == 2 && same_label(by_origin[p] / 3, by_origin[p + 1] / 3))
        joined.emplace_back(by_origin[p], by_origin[p + 1]);
      else
        left.insert(left.end(), by_origin.begin() + static_cast<std::ptrdiff_t>(p),
                    by_origin.begin() + static_cast<std::ptrdiff_t>(q));
      p = q;
    }
    if (joined.empty() || (!left.empty() && left.size() != 2)) return;
    for (const auto& [x, y] : joined) {
      interior_edge[x] = interior_edge[y] = 1;
      parent[find_root(parent, x / 3)] = find_root(parent, y / 3);
    }
    users = left;
  };
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].first == uses[i].first) ++j;
    set_aside_layers(i, j);
    const std::size_t count = users.size();
    if (count == 0) {
      i = j;
      continue;
    }
    const std::uint32_t a = users.front() / 3, b = users.back() / 3;
    // Two faces back to back (a part resting on another, or a face held twice facing both ways;
    // their cuts' vertices shared) where both end: an open border of each, which may turn there.
    const bool back_to_back =
        count == 2 && origin[a] != origin[b] && mesh.area_vector(a).normalized().dot(mesh.area_vector(b).normalized()) < -kParallel;
    const auto lo = static_cast<std::uint32_t>(uses[i].first >> 32), hi = static_cast<std::uint32_t>(uses[i].first & 0xffffffffu);
    if ((count == 1 || back_to_back) && straighten_open_borders) {
      for (const auto& [v, w] : {std::pair{lo, hi}, std::pair{hi, lo}})
        if (open_count[v] < 2) open_ends[v][open_count[v]++] = w;
        else kept[v] = 1;
    } else if (straighten_label_borders && count == 2 && (!same_label(a, b) || origin[a] != origin[b])) {
      for (const auto& [v, w] : {std::pair{lo, hi}, std::pair{hi, lo}}) {
        if (border_count[v] < 2) border_ends[v][border_count[v]] = w;
        if (border_count[v] < 3) ++border_count[v];
      }
    } else if (count != 2 || !same_label(a, b) || back_to_back) {
      kept[lo] = kept[hi] = 1;
    } else if (straighten_open_borders && origin[a] != origin[b]) {
      between_origins[lo] = between_origins[hi] = 1;
    }
    if (count == 2 && same_label(a, b) && origin[a] == origin[b]) {
      interior_edge[users[0]] = interior_edge[users[1]] = 1;
      parent[find_root(parent, a)] = find_root(parent, b);
    }
    i = j;
  }
  for (std::size_t v = 0; v < open_ends.size(); ++v) {
    if (kept[v] || open_count[v] == 0) continue;
    // Kept unless it lies on the segment between its two open neighbours.
    kept[v] = open_count[v] != 2 || between_origins[v] || !on_segment(mesh.positions, v, open_ends[v][0], open_ends[v][1]);
  }
  for (std::size_t v = 0; v < border_ends.size(); ++v)
    if (border_count[v] != 0 && !kept[v])
      kept[v] = border_count[v] != 2 || !on_segment(mesh.positions, v, border_ends[v][0], border_ends[v][1]);
  std::vector<std::vector<std::uint32_t>> regions;
  std::vector<std::uint32_t> region_of(triangle_count, std::numeric_limits<std::uint32_t>::max());
  for (std::uint32_t t = 0; t < triangle_count; ++t) {
    std::uint32_t& r = region_of[find_root(parent, t)];
    if (r == std::numeric_limits<std::uint32_t>::max()) r = static_cast<std::uint32_t>(regions.size()), regions.emplace_back();
    regions[r].push_back(t);
  }
  const std::vector<std::uint32_t> leader = twin_leaders(mesh, regions);
  // A region that keeps its fragments keeps every vertex of them, so neighbours that dropped
  // one of those vertices are re-triangulated with it (else it would be a T-junction there).
  const VertexTriangles around = vertex_triangles(mesh);
  // Whether edge (a, b) is used by a triangle outside region r and its twins that is not
  // parallel to `normal` (one that is lies in the region's plane, on the same edge).
  auto used_outside = [&](std::uint32_t r, std::uint32_t a, std::uint32_t b, const Vec3& normal) {
    const std::uint64_t key = key_of(a, b);
    auto it = std::lower_bound(uses.begin(), uses.end(), std::make_pair(key, std::uint32_t{0}));
    for (; it != uses.end() && it->first == key; ++it) {
      const std::uint32_t t = it->second / 3;
      if (leader[region_of[find_root(parent, t)]] == leader[r]) continue;
      if (!(std::abs(mesh.area_vector(t).normalized().dot(normal)) > kParallel)) return true;
    }
    return false;
  };
  std::vector<std::vector<Triangle>> triangles(regions.size());
  std::vector<char> fragments_kept(regions.size(), 0), queued(regions.size(), 1);
  std::deque<std::uint32_t> todo(regions.size());
  std::iota(todo.begin(), todo.end(), 0u);
  while (!todo.empty()) {
    const std::uint32_t r = todo.front();
    todo.pop_front();
    queued[r] = 0;
    if (leader[r] != r) continue;  // takes its leader's triangles below
    triangles[r].clear();
    const auto elsewhere = [&](std::uint32_t a, std::uint32_t b, const Vec3& normal) { return used_outside(r, a, b, normal); };
    if (regions[r].size() > 1 && retriangulate(mesh, regions[r], interior_edge, kept, options.moved_distance, elsewhere, triangles[r]))
      continue;
    triangles[r].clear();
    fragments_kept[r] = 1;
    for (std::uint32_t t : regions[r]) {
      triangles[r].push_back(mesh.triangles[t]);
      for (std::uint32_t v : mesh.triangles[t]) {
        if (kept[v]) continue;
        kept[v] = 1;
        for (std::uint32_t i = around.first[v]; i < around.first[v + 1]; ++i)
          if (const std::uint32_t other = region_of[find_root(parent, around.triangles[i])]; !fragments_kept[other] && !queued[other])
            queued[other] = 1, todo.push_back(other);
      }
    }
  }
  // Twins: the leader's triangles (turned over where the twin faces the other way), or, where
  // the leader kept its fragments, their own (the same vertices).
  auto facing = [&](std::uint32_t r) {
    Vec3 sum = Vec3::Zero();
    for (std::uint32_t t : regions[r]) sum += mesh.area_vector(t);
    return sum;
  };
  for (std::uint32_t r = 0; r < regions.size(); ++r) {
    if (leader[r] == r) continue;
    triangles[r].clear();
    if (fragments_kept[leader[r]]) {
      for (std::uint32_t t : regions[r]) triangles[r].push_back(mesh.triangles[t]);
      continue;
    }
    const bool turned = facing(r).dot(facing(leader[r])) < 0.0;
    for (Triangle t : triangles[leader[r]]) {
      if (turned) std::swap(t[1], t[2]);
      triangles[r].push_back(t);
    }
  }
  MergedFragments merged;
  merged.mesh.positions = mesh.positions;
  for (std::uint32_t r = 0; r < regions.size(); ++r) {
    merged.mesh.triangles.insert(merged.mesh.triangles.end(), triangles[r].begin(), triangles[r].end());
    merged.representative.insert(merged.representative.end(), triangles[r].size(), regions[r].front());
    if (has_materials) merged.mesh.materials.insert(merged.mesh.materials.end(), triangles[r].size(), mesh.materials[regions[r].front()]);
  }
  return merged;
}

}  // namespace dg
