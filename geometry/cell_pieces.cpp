#include "geometry/cell_pieces.h"

#include "geometry/clip_polygon.h"

namespace dg {

TriangleMesh cut_into_cells(const TriangleMesh& mesh, const VoxelSurface& surface, std::vector<std::uint32_t>& piece_cells) {
  TriangleMesh pieces;
  piece_cells.clear();
  const bool has_materials = mesh.has_materials();
  const double eps = surface.eps();
  for (std::uint32_t cell = 0; cell < surface.cell_count(); ++cell) {
    const VoxelCoord& v = surface.coord(cell);
    const Vec3 lo = eps * Vec3(v[0], v[1], v[2]);
    const Vec3 hi = lo + Vec3::Constant(eps);
    for (std::uint32_t t : surface.triangles(cell)) {
      const auto [a, b, c] = mesh.corners(t);
      const ClipPolygon piece = ClipPolygon::triangle(a, b, c).box(lo, hi);
      if (piece.size < 3 || piece.area() <= 0.0) continue;
      // A piece lying in the voxel's lower face also lies in the neighbour's upper face: keep
      // only that copy, so each piece of surface appears once.
      bool on_lower_face = false;
      for (int axis = 0; axis < 3 && !on_lower_face; ++axis) {
        on_lower_face = true;
        for (int n = 0; n < piece.size; ++n) on_lower_face = on_lower_face && piece.points[n][axis] == lo[axis];
      }
      if (on_lower_face) continue;
      const auto first = static_cast<std::uint32_t>(pieces.positions.size());
      for (int n = 0; n < piece.size; ++n) pieces.positions.push_back(piece.points[n]);
      for (int n = 1; n + 1 < piece.size; ++n) {
        pieces.triangles.push_back({first, first + static_cast<std::uint32_t>(n), first + static_cast<std::uint32_t>(n + 1)});
        piece_cells.push_back(cell);
        if (has_materials) pieces.materials.push_back(mesh.materials[t]);
      }
    }
  }
  return pieces;
}

}  // namespace dg
