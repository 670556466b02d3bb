#include "synthesis/grid_resize.h"

#include "geometry/errors.h"
#include "geometry/flat_faces.h"
#include "geometry/submesh.h"
#include "geometry/t_junctions.h"
#include "grammar/grid_cut.h"
#include "grammar/seam_curve.h"

#include <fmt/format.h>

#include <algorithm>

namespace dg {

void check_counts(const GridRule& grid, const std::vector<int>& counts) {
  if (counts.size() != grid.directions.size())
    throw InputError(fmt::format("grid {} has {} direction(s) but {} count(s) were given", grid.name,
                                 grid.directions.size(), counts.size()));
  for (std::size_t i = 0; i < counts.size(); ++i) {
    const int lowest = lowest_count(grid, i);
    if (counts[i] < lowest || counts[i] > grid.max_count)
      throw InputError(fmt::format("grid {}: count {} of direction {} is outside the allowed range {}..{}{}", grid.name,
                                   counts[i], i + 1, lowest, grid.max_count,
                                   lowest > grid.min_count
                                       ? fmt::format(" (the exemplar's head and tail keep {} unit{} that differ a little "
                                                     "from the repeated one or lie where no plane may cut)",
                                                     min_units(grid.directions[i]), min_units(grid.directions[i]) == 1 ? "" : "s")
                                       : ""));
  }
}

std::vector<RigidTransform> piece_placements(const GridRule& grid, const GridPiece& piece, const std::vector<int>& counts) {
  std::vector<RigidTransform> placements{RigidTransform{}};
  for (std::size_t i = 0; i < grid.directions.size(); ++i) {
    const GridDirection& d = grid.directions[i];
    std::vector<RigidTransform> along;
    if (piece.classes[i] == 0) along.push_back(RigidTransform{});
    if (piece.classes[i] == 1)
      for (int k = 0; k < counts[i] - min_units(d); ++k) along.push_back(k == 0 ? RigidTransform{} : d.motion.after(along.back()));
    if (piece.classes[i] == 2) along.push_back(power(d.motion, counts[i] - d.count));
    std::vector<RigidTransform> combined;
    for (const RigidTransform& a : placements)
      for (const RigidTransform& b : along) combined.push_back(b.after(a));
    placements = std::move(combined);
  }
  return placements;
}

std::size_t resized_size(const GridRule& grid, const std::vector<GridPiece>& pieces, const std::vector<int>& counts) {
  check_counts(grid, counts);
  std::size_t size = 0;
  for (const GridPiece& piece : pieces) {
    std::size_t copies = 1;
    for (std::size_t i = 0; i < grid.directions.size(); ++i)
      if (piece.classes[i] == 1) copies *= static_cast<std::size_t>(std::max(0, counts[i] - min_units(grid.directions[i])));
    size += copies * (piece.mesh.triangles.size() + piece.points.positions.size());
  }
  return size;
}

TriangleMesh resize_grid(const GridRule& grid, const std::vector<GridPiece>& pieces, const std::vector<int>& counts,
                         double eps) {
  check_counts(grid, counts);
  std::vector<std::vector<RigidTransform>> placements;
  std::size_t vertices = 0, triangles = 0;
  for (const GridPiece& piece : pieces) {
    placements.push_back(piece_placements(grid, piece, counts));
    vertices += placements.back().size() * piece.mesh.positions.size();
    triangles += placements.back().size() * piece.mesh.triangles.size();
  }
  // Materials travel with the triangles when every piece carries them.
  const bool with_materials = std::all_of(pieces.begin(), pieces.end(), [](const GridPiece& piece) {
    return piece.mesh.triangles.empty() || piece.mesh.has_materials();
  });
  TriangleMesh result;
  result.positions.reserve(vertices);
  result.triangles.reserve(triangles);
  if (with_materials) result.materials.reserve(triangles);
  std::vector<std::uint32_t> seam_copies;  // per vertex of the result: its copy when on an open edge of its piece
  seam_copies.reserve(vertices);
  std::uint32_t copy = 0;
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    const TriangleMesh& mesh = pieces[p].mesh;
    const std::vector<char> open = open_edge_vertices(mesh);
    for (const RigidTransform& placement : placements[p]) {
      const auto base = static_cast<std::uint32_t>(result.positions.size());
      for (const Vec3& position : mesh.positions) result.positions.push_back(placement.apply(position));
      for (const Triangle& t : mesh.triangles) result.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
      if (with_materials) result.materials.insert(result.materials.end(), mesh.materials.begin(), mesh.materials.end());
      append_seam_labels(seam_copies, open, copy++);
    }
  }
  resolve_t_junctions(result, grid_weld_tolerance(grid, eps), &seam_copies, kSeamWeldFloorFraction * eps);
  close_triangular_holes(result, kSeamHoleFraction * eps);
  drop_hanging_slivers(result, grid_weld_tolerance(grid, eps));
  return merge_flat_faces(result);
}

PointCloud resize_grid_points(const GridRule& grid, const std::vector<GridPiece>& pieces, const std::vector<int>& counts) {
  check_counts(grid, counts);
  PointCloud result;
  for (const GridPiece& piece : pieces)
    for (const RigidTransform& placement : piece_placements(grid, piece, counts))
      append_points(result, transformed(piece.points, placement));
  return result;
}

}  // namespace dg
