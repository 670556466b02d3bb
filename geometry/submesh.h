#pragma once
// Selecting and moving parts of a mesh or a point cloud.

#include "geometry/mesh.h"
#include "geometry/rigid_transform.h"

#include <vector>

namespace dg {

/// The triangles of `mesh` listed in `triangles` (in that order, with their materials) with only
/// the vertices they use, renumbered in first-use order.
TriangleMesh submesh(const TriangleMesh& mesh, const std::vector<std::size_t>& triangles);

/// `mesh` without the vertices no triangle uses (triangles in order, vertices renumbered in
/// first-use order).
TriangleMesh without_unused_vertices(const TriangleMesh& mesh);

/// `mesh` moved by a rigid motion.
TriangleMesh transformed(const TriangleMesh& mesh, const RigidTransform& motion);

/// Appends `part` (vertices, triangles and materials) to `mesh`. Material indices are kept when
/// both sides carry them (or one side has no triangles); otherwise the result has none.
void append_mesh(TriangleMesh& mesh, const TriangleMesh& part);

/// The points of `cloud` listed in `points` (in that order, with their normals when it has them).
PointCloud subcloud(const PointCloud& cloud, const std::vector<std::uint32_t>& points);

/// `cloud` moved by a rigid motion (normals turned with it).
PointCloud transformed(const PointCloud& cloud, const RigidTransform& motion);

/// Appends the points of `part` to `cloud`; normals are kept when both carry them (or `cloud`
/// is empty), else the result has none. An empty `part` changes nothing.
void append_points(PointCloud& cloud, const PointCloud& part);

}  // namespace dg
