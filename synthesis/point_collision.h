#pragma once
// Collision checks between the point-cloud pieces a derivation places: placed points mark the
// cubes of a uniform grid they fall in; a new piece collides when one of its points that is not
// at one of its seams falls in a marked cube (two sampled surfaces that overlap or cross share
// cubes there).

#include "geometry/cell_key.h"
#include "geometry/mesh.h"
#include "synthesis/piece_collision.h"

#include <unordered_set>

namespace dg {

class PointCollisions {
 public:
  /// `cell`: edge of the grid's cubes (model units; the grammar's voxel size eps).
  explicit PointCollisions(double cell);

  /// True when a point of `piece` (model coordinates) that `at_seam` does not accept as contact
  /// falls in a cube holding a point of a piece added before.
  bool collides(const PointCloud& piece, const SeamContact& at_seam) const;

  /// Adds a placed piece to the set later pieces are checked against.
  void add(const PointCloud& piece);

  /// collides(), then add() when it does not collide. Returns whether `piece` was added.
  bool add_unless_collides(const PointCloud& piece, const SeamContact& at_seam);

 private:
  double cell_;
  std::unordered_set<CellKey, CellKeyHash> occupied_;
};

}  // namespace dg
