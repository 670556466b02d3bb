#pragma once
// OpenVDB's own mesh-to-level-set conversion, timed as the reference for the voxel surface.

#include "geometry/mesh.h"

namespace dg::bench {

/// Runs openvdb::tools::meshToLevelSet (half width 3 voxels) on the mesh at voxel size eps and
/// returns the number of active voxels of the result.
std::size_t openvdb_mesh_to_level_set(const TriangleMesh& mesh, double eps);

}  // namespace dg::bench
