#include "geometry/cell_pieces.h"

#include "geometry/clip_polygon.h"

#include <algorithm>
#include <map>
#include <span>
#include <utility>

namespace dg {

namespace {

// Cells of one voxel slab along an axis: cells[begin .. end) all have voxel coordinate `index`.
struct SlabGroup {
  int index;
  std::size_t begin, end;
};

// Clips the triangles of a mesh whose cells carry different keys (see
// cut_where_cell_keys_differ), appending the parts to `out` with their keys.
struct KeyedClipper {
  const TriangleMesh& mesh;
  const VoxelSurface& surface;
  const std::vector<std::uint32_t>& cell_keys;
  TriangleMesh& out;
  std::vector<std::uint32_t>& keys;

  bool uniform(std::span<const std::uint32_t> cells) const {
    return std::all_of(cells.begin(), cells.end(), [&](std::uint32_t c) { return cell_keys[c] == cell_keys[cells.front()]; });
  }

  // Appends polygon `piece` of triangle t, fan-triangulated, each new triangle with `key` and
  // t's material.
  void append(std::uint32_t t, const ClipPolygon& piece, std::uint32_t key) {
    const auto first = static_cast<std::uint32_t>(out.positions.size());
    for (int n = 0; n < piece.size; ++n) out.positions.push_back(piece.points[n]);
    for (int n = 1; n + 1 < piece.size; ++n) {
      out.triangles.push_back({first, first + static_cast<std::uint32_t>(n), first + static_cast<std::uint32_t>(n + 1)});
      keys.push_back(key);
      if (mesh.has_materials()) out.materials.push_back(mesh.materials[t]);
    }
  }

  // `cells` sorted by their coordinate along `axis`, cut into one group per slab.
  std::vector<SlabGroup> slab_groups(std::vector<std::uint32_t>& cells, int axis) const {
    std::stable_sort(cells.begin(), cells.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return surface.coord(a)[axis] < surface.coord(b)[axis]; });
    std::vector<SlabGroup> groups;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const int index = surface.coord(cells[i])[axis];
      if (groups.empty() || groups.back().index != index) groups.push_back({index, i, i});
      groups.back().end = i + 1;
    }
    return groups;
  }

  // Splits `piece` of triangle t (lying in `cells`) into voxel slabs along `axis`, then deeper
  // axes, until the cells of a part share their key; runs of consecutive slabs whose cells all
  // share one key stay one part. A part lying in its slab's lower face is the slab below's.
  void split(std::uint32_t t, const ClipPolygon& piece, int axis, std::vector<std::uint32_t>& cells) {
    if (axis == 3 || uniform(cells)) {
      append(t, piece, cell_keys[cells.front()]);
      return;
    }
    const std::vector<SlabGroup> groups = slab_groups(cells, axis);
    auto cells_of = [&](const SlabGroup& g) { return std::span<const std::uint32_t>(cells.data() + g.begin, g.end - g.begin); };
    for (std::size_t g = 0; g < groups.size();) {
      std::size_t last = g;
      if (uniform(cells_of(groups[g])))
        while (last + 1 < groups.size() && groups[last + 1].index == groups[last].index + 1 &&
               uniform(cells_of(groups[last + 1])) && cell_keys[cells[groups[last + 1].begin]] == cell_keys[cells[groups[g].begin]])
          ++last;
      const double lo = surface.eps() * groups[g].index;
      const ClipPolygon part = piece.slab(axis, lo, surface.eps() * (groups[last].index + 1));
      bool on_lower_face = part.size > 0;
      for (int n = 0; n < part.size; ++n) on_lower_face = on_lower_face && part.points[n][axis] == lo;
      if (part.size >= 3 && part.area() > 0.0 && !on_lower_face) {
        std::vector<std::uint32_t> inside(cells.begin() + static_cast<std::ptrdiff_t>(groups[g].begin),
                                          cells.begin() + static_cast<std::ptrdiff_t>(groups[last].end));
        split(t, part, axis + 1, inside);
      }
      g = last + 1;
    }
  }
};

}  // namespace

TriangleMesh cut_where_cell_keys_differ(const TriangleMesh& mesh, const VoxelSurface& surface,
                                        const std::vector<std::uint32_t>& cell_keys,
                                        std::vector<std::uint32_t>& triangle_keys) {
  std::vector<std::vector<std::uint32_t>> cells_of(mesh.triangles.size());
  for (std::uint32_t cell = 0; cell < surface.cell_count(); ++cell)
    for (std::uint32_t t : surface.triangles(cell)) cells_of[t].push_back(cell);
  TriangleMesh result;
  triangle_keys.clear();
  KeyedClipper clipper{mesh, surface, cell_keys, result, triangle_keys};
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> vertex_of;  // (vertex, key) -> output vertex
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    if (cells_of[t].empty()) continue;
    if (!clipper.uniform(cells_of[t])) {
      const auto [a, b, c] = mesh.corners(t);
      clipper.split(t, ClipPolygon::triangle(a, b, c), 0, cells_of[t]);
      continue;
    }
    const std::uint32_t key = cell_keys[cells_of[t].front()];
    Triangle out;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = mesh.triangles[t][k];
      const auto [at, added] = vertex_of.emplace(std::pair{v, key}, static_cast<std::uint32_t>(result.positions.size()));
      if (added) result.positions.push_back(mesh.positions[v]);
      out[k] = at->second;
    }
    result.triangles.push_back(out);
    triangle_keys.push_back(key);
    if (mesh.has_materials()) result.materials.push_back(mesh.materials[t]);
  }
  return result;
}

}  // namespace dg
