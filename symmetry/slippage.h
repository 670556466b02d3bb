#pragma once
// Slippage analysis (Gelfand & Guibas 2004): the rigid motions that slide a set of oriented
// points along itself, i.e. move every point tangentially to its surface.

#include "geometry/types.h"

#include <vector>

namespace dg {

/// One slippable motion: an infinitesimal rotation `rotation` (axis times rate) and translation.
struct SlippableMotion {
  Vec3 rotation = Vec3::Zero();
  Vec3 translation = Vec3::Zero();
  double eigenvalue_ratio = 0.0;  ///< eigenvalue / largest eigenvalue of the slippage matrix
};

struct SlippageResult {
  std::vector<SlippableMotion> motions;  ///< slippable motions, smallest eigenvalue first
  /// Number of independent slippable motions (0 = locked in place, 6 = degenerate input).
  std::size_t dimension() const { return motions.size(); }
};

/// Analyses points with unit normals (same count). A motion is slippable when its eigenvalue
/// of the 6x6 slippage matrix is below `threshold` times the largest. Points are centred and
/// scaled to unit mean radius first, so the result does not depend on model units.
SlippageResult slippage(const std::vector<Vec3>& points, const std::vector<Vec3>& normals, double threshold = 1e-3);

/// Oriented points of one separate part (points and unit normals, same count).
struct OrientedPoints {
  std::vector<Vec3> points, normals;
};

/// Number of independent rigid motions that slide every part along itself at once: the
/// intersection of each part's slippable motions (slippage() with `threshold`, each part at its
/// own scale). Several small loops at one height around parallel stems slide only along the
/// stems, although analysed as one set their thin band also seems to tilt. One part gives
/// slippage(...).dimension(); parts with fewer than 6 points constrain nothing (no parts: 6).
std::size_t joint_slippage_dimension(const std::vector<OrientedPoints>& parts, double threshold = 1e-3);

}  // namespace dg
