#pragma once
// Small shapes built in code for tests.

#include "geometry/mesh.h"

namespace dg::test {

/// Closed, outward-oriented box [lo, hi] as 12 triangles on 8 vertices.
TriangleMesh make_box(const Vec3& lo, const Vec3& hi);

/// Closed UV sphere of radius `radius` around `centre` with `rings` x `segments` quads.
TriangleMesh make_sphere(const Vec3& centre, double radius, int rings, int segments);

/// Closed, outward-oriented torus: the tube of radius `tube_radius` around the circle of radius
/// `radius` in the plane through `centre` spanned by the first two columns of `frame` (its axis
/// the third), as `segments` x `tube_segments` quads.
TriangleMesh make_torus(const Vec3& centre, const Eigen::Matrix3d& frame, double radius, double tube_radius, int segments,
                        int tube_segments);

/// A chain of `links` interlocking rings (make_torus: radius 1, tube 0.15, 20 x 8 quads) centred
/// at x = 1.5 k, k = 0 .. links - 1: even ones in the x-y plane, odd ones turned a quarter turn
/// about x into the x-z plane. Its feature lines (the tube's edges turn by 45 degrees) are all
/// closed loops.
TriangleMesh make_chain(int links);

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

/// A wall (x along its width, y up, 0.3 thick) with `columns` window boxes per storey, 1.5
/// apart, `storeys` storeys 3 high, and a pilaster (0.3 wide, 0.2 deep, full height) before every
/// third window column and after the last: bays of three windows, 4.5 wide. Touching boxes.
TriangleMesh pilaster_facade(int columns, int storeys);

}  // namespace dg::test
