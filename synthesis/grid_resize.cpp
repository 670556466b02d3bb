#include "synthesis/grid_resize.h"

#include "geometry/errors.h"
#include "geometry/submesh.h"
#include "geometry/t_junctions.h"

#include <fmt/format.h>

namespace dg {

TriangleMesh resize_grid(const GridRule& grid, const std::vector<GridPiece>& pieces, const std::vector<int>& counts,
                         double weld_tolerance) {
  if (counts.size() != grid.directions.size())
    throw InputError(fmt::format("grid {} has {} direction(s) but {} count(s) were given", grid.name,
                                 grid.directions.size(), counts.size()));
  for (std::size_t i = 0; i < counts.size(); ++i)
    if (counts[i] < grid.min_count || counts[i] > grid.max_count)
      throw InputError(fmt::format("grid {}: count {} is outside the allowed range {}..{}", grid.name, counts[i],
                                   grid.min_count, grid.max_count));
  TriangleMesh result;
  for (const GridPiece& piece : pieces) {
    // Offsets of the copies of this piece along each direction, then their sums.
    std::vector<Vec3> offsets{Vec3::Zero()};
    for (std::size_t i = 0; i < grid.directions.size(); ++i) {
      const GridDirection& d = grid.directions[i];
      std::vector<Vec3> along;
      if (piece.classes[i] == 0) along.push_back(Vec3::Zero());
      if (piece.classes[i] == 1)
        for (int k = 0; k < counts[i]; ++k) along.push_back(static_cast<double>(k) * d.translation);
      if (piece.classes[i] == 2) along.push_back(static_cast<double>(counts[i] - d.count) * d.translation);
      std::vector<Vec3> combined;
      for (const Vec3& a : offsets)
        for (const Vec3& b : along) combined.push_back(a + b);
      offsets = std::move(combined);
    }
    for (const Vec3& offset : offsets) {
      RigidTransform shift;
      shift.translation = offset;
      append_mesh(result, transformed(piece.mesh, shift));
    }
  }
  resolve_t_junctions(result, weld_tolerance);
  return result;
}

}  // namespace dg
