#pragma once
// Small shapes built in code for tests.

#include "geometry/mesh.h"

namespace dg::test {

/// Closed, outward-oriented box [lo, hi] as 12 triangles on 8 vertices.
TriangleMesh make_box(const Vec3& lo, const Vec3& hi);

/// Closed UV sphere of radius `radius` around `centre` with `rings` x `segments` quads.
TriangleMesh make_sphere(const Vec3& centre, double radius, int rings, int segments);

/// Appends `part` to `mesh` (indices shifted).
void append(TriangleMesh& mesh, const TriangleMesh& part);

/// `mesh` with every triangle split at its centroid into three: the same surface, triangulated
/// otherwise.
TriangleMesh split_at_centroids(const TriangleMesh& mesh);

/// A rotation about no coordinate axis (0.54, 0.40 and 0.30 rad about z, y and x): a model
/// turned by it has no motion that carries the voxel grid onto itself.
Eigen::Matrix3d general_rotation();

/// Turns every vertex of `mesh` by general_rotation() about the origin.
void turn_generally(TriangleMesh& mesh);

}  // namespace dg::test
