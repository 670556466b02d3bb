#pragma once
// Plane seams of context-free non-terminals: a plane through a docking site's band of voxel-
// surface cells that parts its docker from the rest of the model, at one location or at every
// location of a non-terminal (each placed by its frame).

#include "geometry/rigid_transform.h"
#include "geometry/voxel_surface.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace dg {

/// The plane normal . x = offset (unit normal, model units).
struct Plane {
  Vec3 normal = Vec3::UnitX();
  double offset = 0.0;
  /// Signed distance of p, positive on the side the normal points to.
  double distance(const Vec3& p) const { return normal.dot(p) - offset; }
  /// The plane moved by t.
  Plane moved(const RigidTransform& t) const {
    const Vec3 n = t.apply_direction(normal);
    return {n, n.dot(t.apply(offset * normal))};
  }
};

/// Least-squares plane through the cell centres of a band `site`, or nothing when one of them
/// lies farther than `flatness` (model units) from it. Across a pipe or a bar the plane is
/// perpendicular to the walls the band crosses (the direction its surface normals leave out),
/// else the band's flattest direction. Not oriented.
std::optional<Plane> fit_band_plane(const VoxelSurface& surface, const std::vector<std::uint32_t>& site, double flatness);

/// Orients `plane` so the docker cells next to the band (`site_mask`: one flag per cell) lie on
/// its positive side; false when at least a fifth of them lie on the other side.
bool orient_towards_docker(const VoxelSurface& surface, const std::vector<std::uint32_t>& docker,
                           const std::vector<char>& site_mask, Plane& plane);

/// One location of a seam: its band and docker cells, and the motion from the model to the
/// seam's frame.
struct SeamLocation {
  const std::vector<std::uint32_t>* site = nullptr;
  const std::vector<std::uint32_t>* docker = nullptr;
  RigidTransform to_seam;
};

/// A plane in the seam's frame that parts every location's docker from the rest of the model
/// inside its band: at each location, the docker cells next to the band lie wholly (their
/// whole voxel) on its positive side and the other cells next to the band wholly on its
/// negative side, so a cut along it, confined to the band, leaves the docker's border on the
/// plane however thick or bent the band is. Tried normals: the least-squares ones of
/// fit_band_plane, the seam frame's axes and the direction from the rest's cells towards the
/// docker's; the one leaving the widest gap between the two sides wins, the plane in its
/// middle. Nothing when no normal leaves a gap of at least `min_gap` (model units).
std::optional<Plane> plane_between_sides(const VoxelSurface& surface, std::span<const SeamLocation> locations,
                                         double min_gap);

}  // namespace dg
