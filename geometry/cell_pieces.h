#pragma once
// Cutting mesh triangles along voxel boundaries, so each piece lies in one cell and can be
// coloured (or kept) by that cell's state, e.g. for pictures of symmetric regions.

#include "geometry/mesh.h"
#include "geometry/voxel_surface.h"

#include <cstdint>
#include <vector>

namespace dg {

/// A triangle soup: every triangle of `mesh` clipped to the closed voxel of each cell it
/// touches, fan-triangulated, each piece with its triangle's material (when `mesh` has them).
/// `piece_cells` receives the cell of each output triangle.
/// A face lying exactly on a voxel plane is kept once, in the cell below the plane.
TriangleMesh cut_into_cells(const TriangleMesh& mesh, const VoxelSurface& surface, std::vector<std::uint32_t>& piece_cells);

}  // namespace dg
