#pragma once
// Repetition families: a translation t with its multiples 2t, 3t, ..., a rotation by 360/n with
// its powers, a screw motion with its powers, reported as one generator and a repeat count.

#include "geometry/rigid_transform.h"

#include <cstddef>
#include <string>
#include <vector>

namespace dg {

struct SymmetryFamily {
  RigidTransform generator;
  std::string kind;                  ///< "translation", "rotation" or "screw"
  std::vector<std::size_t> members;  ///< indices into the motions given to group_families
  std::vector<int> powers;           ///< generator power of each member (member = generator^power)
  /// Repeats of the generator: the largest k such that the powers 1, 2, ..., k were all found
  /// and each repeats a unit rather than only sliding parts along themselves (fence of n inner
  /// posts: n - 1; its rails alone match n pitches apart and its end posts n + 1 apart). For
  /// a rotation whose angle divides 360 degrees into n steps, powers k and n - k are one motion
  /// up to inversion, so finding either gives both.
  std::size_t count = 0;
  int order = 0;  ///< rotations: n when the generator angle is 360/n degrees, else 0
};

/// Groups canonical motions (see canonical_motion) into families. `repeats[i]` is non-zero when
/// motion i repeats a unit (it counts towards the family's count), zero when it only slides
/// (it still joins the family). `eps` is the positional tolerance in model units, `centre` a
/// point near the model used to compare motions.
/// Every motion belongs to exactly one family; families keep the input order of their
/// smallest member.
std::vector<SymmetryFamily> group_families(const std::vector<RigidTransform>& motions, const std::vector<std::string>& kinds,
                                           const std::vector<char>& repeats, const Vec3& centre, double eps);

}  // namespace dg
