#include "grammar/grid_seams.h"

#include "geometry/topology.h"
#include "grammar/grid_cut.h"

#include <algorithm>
#include <cmath>

namespace dg {
namespace {

// Open edges (used by one triangle of their piece) of the pieces whose class along direction
// `i` is `piece_class`, with both ends on plane `plane` of that direction (within 1e-4 eps),
// moved by `placement`.
std::vector<Segment> plane_seam(const GridRule& grid, const std::vector<GridPiece>& pieces, std::size_t i, int piece_class,
                                int plane, const RigidTransform& placement, double eps) {
  const GridDirection& d = grid.directions[i];
  const double offset = d.cut + plane * d.pitch;
  auto on_plane = [&](const Vec3& p) { return std::abs(d.direction.dot(p) - offset) <= 1e-4 * eps; };
  std::vector<Segment> seam;
  for (const GridPiece& piece : pieces) {
    if (piece.classes[i] != piece_class || piece.mesh.triangles.empty()) continue;
    const EdgeUsers users = edge_users(piece.mesh);
    for (std::uint32_t corner = 0; corner < 3 * piece.mesh.triangles.size(); ++corner) {
      if (users.group_end[corner] - users.group_begin[corner] != 1) continue;
      const Triangle& t = piece.mesh.triangles[corner / 3];
      const Vec3& a = piece.mesh.positions[t[corner % 3]];
      const Vec3& b = piece.mesh.positions[t[(corner + 1) % 3]];
      if (on_plane(a) && on_plane(b)) seam.push_back({placement.apply(a), placement.apply(b)});
    }
  }
  return seam;
}

// Misfit of two seams that a resize joins; 0 when either is empty, infinity when they do not
// meet within eps.
double joined_misfit(const std::vector<Segment>& a, const std::vector<Segment>& b, double eps) {
  if (a.empty() || b.empty()) return 0.0;
  return seam_misfit(a, b, eps, eps);
}

}  // namespace

double grid_seam_misfit(const GridRule& grid, const std::vector<GridPiece>& pieces, double eps) {
  double misfit = 0.0;
  auto join = [&](double m) {
    if (std::isfinite(m)) misfit = std::max(misfit, m);
  };
  for (std::size_t i = 0; i < grid.directions.size(); ++i) {
    const GridDirection& d = grid.directions[i];
    const int head_top = d.head_units, unit_top = d.head_units + 1, tail_bottom = d.count - d.tail_units;
    const std::vector<Segment> unit_upper = plane_seam(grid, pieces, i, 1, unit_top, {}, eps);
    join(joined_misfit(unit_upper, plane_seam(grid, pieces, i, 1, head_top, d.motion, eps), eps));
    join(joined_misfit(unit_upper, plane_seam(grid, pieces, i, 2, tail_bottom, power(d.motion, unit_top - tail_bottom), eps), eps));
    if (lowest_count(grid, i) == min_units(d))
      join(joined_misfit(plane_seam(grid, pieces, i, 0, head_top, {}, eps),
                         plane_seam(grid, pieces, i, 2, tail_bottom, power(d.motion, head_top - tail_bottom), eps), eps));
  }
  return misfit;
}

double grid_weld_tolerance(const GridRule& grid, double eps) {
  return std::max(kSeamWeldFloorFraction * eps, 2.0 * grid.seam_misfit);
}

}  // namespace dg
