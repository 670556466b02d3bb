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

}  // namespace dg::test
