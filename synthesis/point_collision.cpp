#include "synthesis/point_collision.h"

#include <algorithm>

namespace dg {

PointCollisions::PointCollisions(double cell) : cell_(cell) {}

bool PointCollisions::collides(const PointCloud& piece, const SeamContact& at_seam) const {
  return std::any_of(piece.positions.begin(), piece.positions.end(),
                     [&](const Vec3& p) { return occupied_.contains(cell_key(p, cell_)) && !at_seam(p); });
}

void PointCollisions::add(const PointCloud& piece) {
  for (const Vec3& p : piece.positions) occupied_.insert(cell_key(p, cell_));
}

bool PointCollisions::add_unless_collides(const PointCloud& piece, const SeamContact& at_seam) {
  if (collides(piece, at_seam)) return false;
  add(piece);
  return true;
}

}  // namespace dg
