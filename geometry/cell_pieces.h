#pragma once
// Cutting mesh triangles along voxel boundaries where the cells' states differ, so each piece
// can be coloured by the state of the cells it lies in, e.g. for pictures of symmetric regions.

#include "geometry/mesh.h"
#include "geometry/voxel_surface.h"

#include <cstdint>
#include <vector>

namespace dg {

/// `mesh` with a key per triangle from the keys of the cells it touches (`cell_keys`, one per
/// cell, e.g. a colour's index): a triangle whose cells all share a key stays whole; others are
/// clipped to voxel slabs along x, then y, then z, runs of slabs whose cells share a key kept
/// as one polygon (fan-triangulated), down to single voxels where keys differ. A piece lying in
/// a voxel plane belongs to the voxel below it. Cell indices as keys cut each triangle into its
/// cell pieces. Vertices are shared only between whole triangles of one key (so per-vertex
/// colours stay crisp); triangles in no cell are left out. Materials travel with the triangles;
/// `triangle_keys` receives the key of each output triangle.
TriangleMesh cut_where_cell_keys_differ(const TriangleMesh& mesh, const VoxelSurface& surface,
                                        const std::vector<std::uint32_t>& cell_keys,
                                        std::vector<std::uint32_t>& triangle_keys);

}  // namespace dg
