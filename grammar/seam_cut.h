#pragma once
// Building a non-terminal's seam from the docking site of its first location, and cutting or
// judging the model along that seam at any location (placed by the location's frame).

#include "geometry/voxel_surface.h"
#include "geometry/rigid_transform.h"
#include "geometry/zone_cut.h"
#include "grammar/seam_surface.h"

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

/// Whether a seam face on voxel plane `plane` across `axis` meets the box of `corners` (seam
/// frame, model units; faces next to the box count too). Decides which pieces a voxel seam cuts.
bool crosses_face(const SeamSurface& seam, const std::array<Vec3, 3>& corners, int axis, std::int32_t plane);

/// Side of model point p at a location with `frame` (seam frame -> model): the plane's positive
/// side, or for voxel seams the docker-side flag of the seam's voxel holding frame^-1(p) (points
/// on a voxel plane count in the voxel below; cells of the exemplar at the seam's own location,
/// `docker_side` as from voxel_seam).
bool on_docker_side(const SeamSurface& seam, const VoxelSurface& surface, const std::vector<char>& docker_side,
                    const RigidTransform& frame_inverse, const Vec3& p);

}  // namespace dg
