#include "geometry/cell_pieces.h"

#include "geometry/clip_polygon.h"

#include <algorithm>
#include <functional>
#include <map>
#include <span>
#include <utility>

namespace dg {

namespace {

// Appends polygon `piece` of triangle t of `mesh`, fan-triangulated, each new triangle with
// `key` and t's material.
void append_polygon(const TriangleMesh& mesh, std::uint32_t t, const ClipPolygon& piece, std::uint32_t key,
                    TriangleMesh& out, std::vector<std::uint32_t>& keys) {
  const auto first = static_cast<std::uint32_t>(out.positions.size());
  for (int n = 0; n < piece.size; ++n) out.positions.push_back(piece.points[n]);
  for (int n = 1; n + 1 < piece.size; ++n) {
    out.triangles.push_back({first, first + static_cast<std::uint32_t>(n), first + static_cast<std::uint32_t>(n + 1)});
    keys.push_back(key);
    if (mesh.has_materials()) out.materials.push_back(mesh.materials[t]);
  }
}

}  // namespace

TriangleMesh cut_where_cell_keys_differ(const TriangleMesh& mesh, const VoxelSurface& surface,
                                        const std::vector<std::uint32_t>& cell_keys,
                                        std::vector<std::uint32_t>& triangle_keys) {
  std::vector<std::vector<std::uint32_t>> cells_of(mesh.triangles.size());
  for (std::uint32_t cell = 0; cell < surface.cell_count(); ++cell)
    for (std::uint32_t t : surface.triangles(cell)) cells_of[t].push_back(cell);
  auto uniform = [&](std::span<const std::uint32_t> cells) {
    return std::all_of(cells.begin(), cells.end(), [&](std::uint32_t c) { return cell_keys[c] == cell_keys[cells.front()]; });
  };
  TriangleMesh result;
  triangle_keys.clear();
  // Splits `piece` (lying in `cells`) into voxel slabs along `axis` and deeper axes until the
  // cells of a part share their key; a part lying in a slab's lower face is the slab below's.
  std::function<void(const ClipPolygon&, int, std::vector<std::uint32_t>&, std::uint32_t)> split =
      [&](const ClipPolygon& piece, int axis, std::vector<std::uint32_t>& cells, std::uint32_t t) {
        if (uniform(cells) || axis == 3) {
          append_polygon(mesh, t, piece, cell_keys[cells.front()], result, triangle_keys);
          return;
        }
        std::stable_sort(cells.begin(), cells.end(), [&](std::uint32_t a, std::uint32_t b) {
          return surface.coord(a)[axis] < surface.coord(b)[axis];
        });
        // Runs of consecutive slabs whose cells all share one key are clipped as one part.
        for (std::size_t begin = 0; begin < cells.size();) {
          const int first_index = surface.coord(cells[begin])[axis];
          int last_index = first_index;
          std::size_t end = begin;
          while (end < cells.size() && surface.coord(cells[end])[axis] == first_index) ++end;
          std::span<const std::uint32_t> group(cells.data() + begin, end - begin);
          if (uniform(group)) {
            const std::uint32_t key = cell_keys[cells[begin]];
            while (end < cells.size()) {
              const int next = surface.coord(cells[end])[axis];
              std::size_t next_end = end;
              while (next_end < cells.size() && surface.coord(cells[next_end])[axis] == next) ++next_end;
              std::span<const std::uint32_t> next_group(cells.data() + end, next_end - end);
              if (next != last_index + 1 || !uniform(next_group) || cell_keys[cells[end]] != key) break;
              last_index = next;
              end = next_end;
            }
          }
          const double lo = surface.eps() * first_index;
          const ClipPolygon part = piece.slab(axis, lo, surface.eps() * (last_index + 1));
          bool on_lower_face = part.size > 0;
          for (int n = 0; n < part.size; ++n) on_lower_face = on_lower_face && part.points[n][axis] == lo;
          if (part.size >= 3 && part.area() > 0.0 && !on_lower_face) {
            std::vector<std::uint32_t> inside(cells.begin() + static_cast<std::ptrdiff_t>(begin),
                                              cells.begin() + static_cast<std::ptrdiff_t>(end));
            split(part, axis + 1, inside, t);
          }
          begin = end;
        }
      };
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> vertex_of;  // (vertex, key) -> output vertex
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    if (cells_of[t].empty()) continue;
    if (!uniform(cells_of[t])) {
      const auto [a, b, c] = mesh.corners(t);
      split(ClipPolygon::triangle(a, b, c), 0, cells_of[t], t);
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
