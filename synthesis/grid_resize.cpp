#include "synthesis/grid_resize.h"

#include "geometry/errors.h"
#include "geometry/t_junctions.h"

#include <fmt/format.h>

namespace dg {
namespace {

// Offsets of the copies of `piece` (model units): per direction, the origin for a head piece,
// k times the translation (k = 0 .. count-1) for a unit piece, the shift of the tail for a tail
// piece; the copies are all combinations.
std::vector<Vec3> piece_offsets(const GridRule& grid, const GridPiece& piece, const std::vector<int>& counts) {
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
  return offsets;
}

}  // namespace

TriangleMesh resize_grid(const GridRule& grid, const std::vector<GridPiece>& pieces, const std::vector<int>& counts,
                         double weld_tolerance) {
  if (counts.size() != grid.directions.size())
    throw InputError(fmt::format("grid {} has {} direction(s) but {} count(s) were given", grid.name,
                                 grid.directions.size(), counts.size()));
  for (std::size_t i = 0; i < counts.size(); ++i)
    if (counts[i] < grid.min_count || counts[i] > grid.max_count)
      throw InputError(fmt::format("grid {}: count {} is outside the allowed range {}..{}", grid.name, counts[i],
                                   grid.min_count, grid.max_count));
  std::vector<std::vector<Vec3>> offsets;
  std::size_t vertices = 0, triangles = 0;
  for (const GridPiece& piece : pieces) {
    offsets.push_back(piece_offsets(grid, piece, counts));
    vertices += offsets.back().size() * piece.mesh.positions.size();
    triangles += offsets.back().size() * piece.mesh.triangles.size();
  }
  TriangleMesh result;
  result.positions.reserve(vertices);
  result.triangles.reserve(triangles);
  std::vector<char> seam_vertices;  // per vertex of the result: lies on an open edge of its piece
  seam_vertices.reserve(vertices);
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    const TriangleMesh& mesh = pieces[p].mesh;
    const std::vector<char> open = open_edge_vertices(mesh);
    for (const Vec3& offset : offsets[p]) {
      const auto base = static_cast<std::uint32_t>(result.positions.size());
      for (const Vec3& position : mesh.positions) result.positions.push_back(position + offset);
      for (const Triangle& t : mesh.triangles) result.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
      seam_vertices.insert(seam_vertices.end(), open.begin(), open.end());
    }
  }
  resolve_t_junctions(result, weld_tolerance, &seam_vertices);
  return result;
}

}  // namespace dg
