#pragma once
// Building a non-terminal's seam from the docking site of its first location, and cutting or
// judging the model along that seam at any location (placed by the location's frame).

#include "geometry/voxel_surface.h"
#include "geometry/rigid_transform.h"
#include "geometry/zone_cut.h"
#include "grammar/seam_surface.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace dg {

/// The voxel-face seam of a docking site (model frame): band cells next to the docker (26-
/// neighbours) and the docker itself are on the docker side; the seam is every face between a
/// docker-side band voxel and a voxel not on the docker side. `docker_side` receives one flag
/// per cell. The faces are empty when the band has no cell next to the docker.
SeamSurface voxel_seam(const VoxelSurface& surface, const std::vector<std::uint32_t>& site,
                       const std::vector<std::uint32_t>& docker, std::vector<char>& docker_side);

/// Planes to cut along so the seam, placed by `frame`, becomes edges of the mesh: the plane
/// itself, or the voxel planes of the seam's grid across the box of its faces (one voxel more
/// on each side), one family per axis of the seam's frame (x, y, z).
std::vector<PlaneFamily> seam_planes(const SeamSurface& seam, const RigidTransform& frame);

/// The faces of a voxel seam grouped by the plane they lie on, for range queries.
class SeamFaceIndex {
 public:
  explicit SeamFaceIndex(const SeamSurface& seam);

  /// Whether a face on voxel plane `plane` across `axis` with voxel index j along axis
  /// (axis + 1) % 3 in [j0, j1] and l along (axis + 2) % 3 in [l0, l1] passes `accept(j, l)`.
  template <class Accept>
  bool any_in(int axis, std::int32_t plane, std::int64_t j0, std::int64_t j1, std::int64_t l0, std::int64_t l1,
              Accept accept) const {
    // Walk the rows j of the plane that hold faces, from column l0 to l1 in each.
    auto at = std::lower_bound(keys_.begin(), keys_.end(), Key{axis, plane, j0, l0});
    while (at != keys_.end() && (*at)[0] == axis && (*at)[1] == plane && (*at)[2] <= j1) {
      const std::int64_t j = (*at)[2], l = (*at)[3];
      if (l < l0) {
        at = std::lower_bound(at, keys_.end(), Key{axis, plane, j, l0});
      } else if (l > l1) {
        at = std::lower_bound(at, keys_.end(), Key{axis, plane, j + 1, l0});
      } else if (accept(j, l)) {
        return true;
      } else {
        ++at;
      }
    }
    return false;
  }

  /// Voxel edge length of the seam, model units.
  double eps() const { return eps_; }

 private:
  using Key = std::array<std::int64_t, 4>;  // axis, plane, j, l
  std::vector<Key> keys_;                   // ascending
  double eps_ = 0.0;
};

/// Whether a seam face on voxel plane `plane` across `axis` meets the chord along which the
/// triangle `corners` (seam frame, model units) crosses that plane, within 1e-6 eps. Decides
/// which pieces a voxel seam cuts: only those the seam passes through, so a large triangle is
/// not cut along every plane that has a seam face somewhere in its bounding box.
bool crosses_face(const SeamFaceIndex& faces, const std::array<Vec3, 3>& corners, int axis, std::int32_t plane);

/// Side of model point p at a location with `frame` (seam frame -> model): the plane's positive
/// side, or for voxel seams the docker-side flag of the seam's voxel holding frame^-1(p) (points
/// on a voxel plane count in the voxel below; cells of the exemplar at the seam's own location,
/// `docker_side` as from voxel_seam).
bool on_docker_side(const SeamSurface& seam, const VoxelSurface& surface, const std::vector<char>& docker_side,
                    const RigidTransform& frame_inverse, const Vec3& p);

}  // namespace dg
