#pragma once
// Which part of a symmetric region a motion pins in place, as opposed to sliding it along
// itself: long rails match under any shift along them, posts only under the exact pitch.

#include "geometry/rigid_transform.h"
#include "geometry/voxel_surface.h"
#include "symmetry/symmetric_region.h"

#include <cstdint>
#include <vector>

namespace dg {

/// The real power t^s: rotation by s times t's angle about t's screw axis and slide by s times
/// its slide along it (translations: s times the translation).
RigidTransform fractional_power(const RigidTransform& t, double s);

/// Area (model units^2, surface cell areas) of the cells of `region` (symmetric under t) that
/// stop being symmetric under the slightly longer motion t^(1+s), with s chosen so that the
/// fastest cell moves about `shift` model units under t^s (use less than r, so that
/// r-symmetric cells of a sliding part stay symmetric). Cells that only slide along themselves
/// (rails, walls, cylinders about a rotation axis) do not count. Large regions are estimated
/// from 8192 evenly strided cells. Parallel, deterministic.
double pinned_area(const CellMatcher& matcher, const VoxelSurface& surface, const RigidTransform& t,
                   const std::vector<std::uint32_t>& region, double shift);

}  // namespace dg
