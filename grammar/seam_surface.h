#pragma once
// The seam of a context-free non-terminal: the surface its dockers are cut along, in the
// non-terminal's own frame. Either one plane (bands that lie flat) or a set of voxel faces of
// the analysis grid (any band): the faces between band voxels on the docker side and voxels
// outside it.

#include "geometry/types.h"

#include <array>
#include <cstdint>
#include <vector>

namespace dg {

/// Face of voxel (i, j, k) on its lower side across `axis` (0 = x, 1 = y, 2 = z): the unit
/// square at coordinate i (or j, k) of that axis, spanning [j, j+1] x [k, k+1] in the others
/// (times eps).
struct VoxelFace {
  std::array<std::int32_t, 3> voxel{};
  int axis = 0;
  auto operator<=>(const VoxelFace&) const = default;
};

struct SeamSurface {
  enum class Kind { plane, voxel_faces };
  Kind kind = Kind::plane;
  Vec3 normal = Vec3::UnitX();  ///< plane: n . x = offset, the docker on the side n points to
  double offset = 0.0;
  double eps = 0.0;                ///< voxel faces: voxel edge length, model units
  std::vector<VoxelFace> faces;    ///< voxel faces: ascending

  /// True when point p (in the seam's frame, model units) lies within `tolerance` of the seam.
  bool near(const Vec3& p, double tolerance) const;
};

}  // namespace dg
