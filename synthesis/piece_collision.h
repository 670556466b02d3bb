#pragma once
// Collision checks between the pieces a derivation places (paper 001 §3.2, §4.2): Embree's
// BVH collision query finds triangle pairs whose boxes overlap, an exact edge/triangle test
// decides. Pieces of a grammar meet only at their seams, so intersections the caller places at
// a seam of the new piece (e.g. within a tolerance of its seam planes or voxel faces) are
// contact, not collision.

#include "geometry/mesh.h"

#include <functional>
#include <memory>
#include <vector>

namespace dg {

/// Whether an intersection point (model units) is contact at a seam rather than a collision.
/// Called concurrently: must only read shared state.
using SeamContact = std::function<bool(const Vec3&)>;

class PieceCollisions {
 public:
  /// `margin`: placed pieces whose bounds are farther than this from the new piece are skipped
  /// (model units, at least the seam tolerance the contact test uses).
  explicit PieceCollisions(double margin);
  ~PieceCollisions();
  PieceCollisions(const PieceCollisions&) = delete;
  PieceCollisions& operator=(const PieceCollisions&) = delete;

  /// True when `piece` (model coordinates) crosses or touches a piece added before at a point
  /// that `at_seam` does not accept as contact (touching within 1e-9 of the triangles' and
  /// edges' parameter ranges). Coplanar overlaps are not detected.
  bool collides(const TriangleMesh& piece, const SeamContact& at_seam) const;

  /// Adds a placed piece to the set later pieces are checked against.
  void add(const TriangleMesh& piece);

  /// collides(), then add() when it does not collide: one collision structure serves both.
  /// Returns whether `piece` was added.
  bool add_unless_collides(const TriangleMesh& piece, const SeamContact& at_seam);

  std::size_t pieces() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace dg
