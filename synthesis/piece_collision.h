#pragma once
// Collision checks between the pieces a derivation places (paper 001 §3.2, §4.2): Embree's
// BVH collision query finds triangle pairs whose boxes overlap, an exact edge/triangle test
// decides. Pieces of a grammar meet only at their seams, so intersections within a tolerance
// band around the seam planes of the new piece are contact, not collision.

#include "geometry/mesh.h"

#include <memory>
#include <vector>

namespace dg {

/// A plane n . x = offset (n unit), model units.
struct SeamPlane {
  Vec3 normal = Vec3::UnitX();
  double offset = 0.0;
};

class PieceCollisions {
 public:
  /// `seam_tolerance`: intersections closer than this to a seam plane are allowed (model units).
  explicit PieceCollisions(double seam_tolerance);
  ~PieceCollisions();
  PieceCollisions(const PieceCollisions&) = delete;
  PieceCollisions& operator=(const PieceCollisions&) = delete;

  /// True when `piece` (model coordinates) crosses a piece added before anywhere farther than
  /// the tolerance from all of `seams`. Coplanar overlaps are not detected.
  bool collides(const TriangleMesh& piece, const std::vector<SeamPlane>& seams) const;

  /// Adds a placed piece to the set later pieces are checked against.
  void add(const TriangleMesh& piece);

  std::size_t pieces() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace dg
