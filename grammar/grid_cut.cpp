#include "grammar/grid_cut.h"

#include "geometry/flat_faces.h"
#include "geometry/fragment_merge.h"
#include "geometry/slab_cut.h"
#include "geometry/submesh.h"

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <numeric>

namespace dg {
namespace {

constexpr std::uint32_t kNoTwin = std::numeric_limits<std::uint32_t>::max();

// Per triangle of `mesh`: the earlier triangle it doubles back to back (the same corners in the
// opposite order and the same material), or kNoTwin; a triangle is the twin of at most one other.
std::vector<std::uint32_t> back_to_back_twins(const TriangleMesh& mesh) {
  std::map<std::array<std::uint32_t, 3>, std::vector<std::uint32_t>> unpaired;  // sorted corners -> triangles
  std::vector<std::uint32_t> twin(mesh.triangles.size(), kNoTwin);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    std::array<std::uint32_t, 3> key{tri[0], tri[1], tri[2]};
    std::sort(key.begin(), key.end());
    std::vector<std::uint32_t>& candidates = unpaired[key];
    const Triangle reversed{tri[0], tri[2], tri[1]};
    const auto match = std::find_if(candidates.begin(), candidates.end(), [&](std::uint32_t u) {
      if (mesh.has_materials() && mesh.materials[u] != mesh.materials[t]) return false;
      const Triangle& other = mesh.triangles[u];
      for (int k = 0; k < 3; ++k)
        if (other[k] == reversed[0] && other[(k + 1) % 3] == reversed[1]) return true;
      return false;
    });
    if (match == candidates.end()) {
      candidates.push_back(t);
    } else {
      twin[t] = *match;
      candidates.erase(match);
    }
  }
  return twin;
}

// `mesh` without the later triangle of each back-to-back pair, into `sheet` (same vertices);
// returns one flag per triangle of `sheet`: 1 when its twin was dropped.
std::vector<char> drop_twins(const TriangleMesh& mesh, TriangleMesh& sheet) {
  const std::vector<std::uint32_t> twin = back_to_back_twins(mesh);
  sheet.positions = mesh.positions;
  sheet.triangles.clear();
  sheet.materials.clear();
  std::vector<std::uint32_t> sheet_index(mesh.triangles.size(), kNoTwin);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    if (twin[t] == kNoTwin) {
      sheet_index[t] = static_cast<std::uint32_t>(sheet.triangles.size());
      sheet.triangles.push_back(mesh.triangles[t]);
      if (mesh.has_materials()) sheet.materials.push_back(mesh.materials[t]);
    }
  std::vector<char> doubled(sheet.triangles.size(), 0);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    if (twin[t] != kNoTwin) doubled[sheet_index[twin[t]]] = 1;
  return doubled;
}

// cut_along_grid of every triangle of `mesh` (no part kept whole).
GridCut cut_across_whole_model(const TriangleMesh& mesh, const GridRule& grid, double eps) {
  TriangleMesh cut;
  // Back-to-back double faces are cut as one sheet and doubled again at the end, so both sides
  // stay exact duplicates (and their edges manifold for the merge below).
  const std::vector<char> doubled = drop_twins(mesh, cut);
  const std::vector<std::uint32_t> group = flat_faces(cut, doubled, 1e-6 * eps);
  std::vector<std::uint32_t> origin(cut.triangles.size());  // sheet triangle of each fragment
  std::iota(origin.begin(), origin.end(), 0u);
  std::vector<std::vector<double>> planes;
  for (const GridDirection& direction : grid.directions) {
    std::vector<double> offsets;
    for (int j = 0; j <= direction.count; ++j) offsets.push_back(direction.cut + j * direction.pitch);
    cut = cut_along_planes(cut, direction.direction, offsets, 1e-6 * eps, &origin);
    planes.push_back(std::move(offsets));
  }
  std::vector<std::vector<std::size_t>> slabs(cut.triangles.size());
  std::map<std::vector<std::size_t>, std::uint32_t> cells;  // slab tuple -> label
  std::vector<std::uint32_t> label(cut.triangles.size()), face(cut.triangles.size());
  for (std::size_t t = 0; t < cut.triangles.size(); ++t) {
    for (std::size_t i = 0; i < grid.directions.size(); ++i)
      slabs[t].push_back(slab_of(cut, t, grid.directions[i].direction, planes[i]));
    label[t] = cells.try_emplace(slabs[t], static_cast<std::uint32_t>(cells.size())).first->second;
    face[t] = group[origin[t]];
  }
  // The planes cut whole triangles, and one plane after another: join the fragments of each
  // flat face of the exemplar within a cell again, keeping the exemplar's vertices and only
  // those cut vertices where the cell borders turn or meet an edge between faces.
  std::vector<char> pinned(cut.positions.size(), 0);
  std::fill(pinned.begin(), pinned.begin() + static_cast<std::ptrdiff_t>(mesh.positions.size()), 1);
  const MergedFragments merged = merge_fragments(cut, face, label, pinned, {.straighten_label_borders = true});
  GridCut result;
  result.mesh.positions = merged.mesh.positions;
  for (std::size_t t = 0; t < merged.mesh.triangles.size(); ++t) {
    const Triangle& tri = merged.mesh.triangles[t];
    const std::uint32_t r = merged.representative[t];
    result.mesh.triangles.push_back(tri);
    result.slabs.push_back(slabs[r]);
    if (cut.has_materials()) result.mesh.materials.push_back(cut.materials[r]);
    if (!doubled[origin[r]]) continue;
    result.mesh.triangles.push_back({tri[0], tri[2], tri[1]});
    result.slabs.push_back(slabs[r]);
    if (cut.has_materials()) result.mesh.materials.push_back(cut.materials[r]);
  }
  result.mesh = without_unused_vertices(result.mesh);
  return result;
}

// cut_along_grid for a 1-grid that keeps parts whole: the rest cut along the planes, the parts
// appended uncut in the head's slab 0 or the tail's slab count + 1.
GridCut cut_around_whole_parts(const TriangleMesh& mesh, const GridRule& grid, double eps) {
  const GridDirection& direction = grid.directions[0];
  std::vector<char> whole(mesh.triangles.size(), 0);
  for (std::uint32_t t : direction.whole_in_head) whole[t] = 1;
  for (std::uint32_t t : direction.whole_in_tail) whole[t] = 2;
  std::vector<std::size_t> rest;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (!whole[t]) rest.push_back(t);
  GridCut cut = cut_across_whole_model(submesh(mesh, rest), grid, eps);
  for (char side : {char{1}, char{2}}) {
    std::vector<std::size_t> triangles;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      if (whole[t] == side) triangles.push_back(t);
    const TriangleMesh parts = submesh(mesh, triangles);
    const bool materials = cut.mesh.has_materials() && parts.has_materials();
    const auto offset = static_cast<std::uint32_t>(cut.mesh.positions.size());
    cut.mesh.positions.insert(cut.mesh.positions.end(), parts.positions.begin(), parts.positions.end());
    for (std::size_t t = 0; t < parts.triangles.size(); ++t) {
      const Triangle& tri = parts.triangles[t];
      cut.mesh.triangles.push_back({tri[0] + offset, tri[1] + offset, tri[2] + offset});
      if (materials) cut.mesh.materials.push_back(parts.materials[t]);
      cut.slabs.push_back({side == 1 ? std::size_t{0} : static_cast<std::size_t>(direction.count) + 1});
    }
  }
  return cut;
}

}  // namespace

GridCut cut_along_grid(const TriangleMesh& mesh, const GridRule& grid, double eps) {
  const bool keeps_parts = grid.directions.size() == 1 &&
                           !(grid.directions[0].whole_in_head.empty() && grid.directions[0].whole_in_tail.empty());
  return keeps_parts ? cut_around_whole_parts(mesh, grid, eps) : cut_across_whole_model(mesh, grid, eps);
}

std::vector<GridPiece> cut_grid_pieces(const TriangleMesh& mesh, const GridRule& grid, double eps) {
  const GridCut grid_cut = cut_along_grid(mesh, grid, eps);
  const TriangleMesh& cut = grid_cut.mesh;
  std::map<std::vector<int>, std::vector<std::size_t>> by_class;
  for (std::size_t t = 0; t < cut.triangles.size(); ++t) {
    std::vector<int> classes;
    for (std::size_t i = 0; i < grid.directions.size(); ++i) {
      const int c = slab_class(grid_cut.slabs[t][i], grid.directions[i]);
      if (c < 0) break;
      classes.push_back(c);
    }
    if (classes.size() != grid.directions.size()) continue;  // lies in a copy of a unit
    by_class[classes].push_back(t);
  }
  std::vector<GridPiece> pieces;
  for (const auto& [classes, triangles] : by_class) pieces.push_back({classes, submesh(cut, triangles), {}});
  return pieces;
}

std::size_t slab_of_point(const GridDirection& direction, const Vec3& point) {
  // Planes cut + j pitch, j = 0 .. count.
  const double planes_below = std::floor((direction.direction.dot(point) - direction.cut) / direction.pitch) + 1.0;
  return static_cast<std::size_t>(std::clamp(planes_below, 0.0, static_cast<double>(direction.count + 1)));
}

std::vector<GridPiece> cut_grid_points(const PointCloud& cloud, const GridRule& grid) {
  std::map<std::vector<int>, std::vector<std::size_t>> by_class;
  for (std::size_t p = 0; p < cloud.positions.size(); ++p) {
    std::vector<int> classes;
    for (const GridDirection& direction : grid.directions) {
      const int c = slab_class(slab_of_point(direction, cloud.positions[p]), direction);
      if (c < 0) break;
      classes.push_back(c);
    }
    if (classes.size() == grid.directions.size()) by_class[classes].push_back(p);
  }
  std::vector<GridPiece> pieces;
  for (const auto& [classes, indices] : by_class) {
    GridPiece piece{classes, {}, {}};
    for (std::size_t p : indices) {
      piece.points.positions.push_back(cloud.positions[p]);
      if (cloud.has_normals()) piece.points.normals.push_back(cloud.normals[p]);
    }
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

int slab_class(std::size_t slab, const GridDirection& direction) {
  const auto k = static_cast<int>(slab);
  if (k <= direction.head_units) return 0;
  if (k == direction.head_units + 1) return 1;
  if (k > direction.count - direction.tail_units) return 2;
  return -1;
}

std::string piece_name(const std::vector<int>& classes) {
  std::string name = "r";
  for (int c : classes) name += std::to_string(c + 1);
  return name;
}

}  // namespace dg
