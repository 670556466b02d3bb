#pragma once
// Distances between meshes for tests: a sampled symmetric Hausdorff distance.

#include "geometry/mesh.h"

namespace dg::test {

/// Distance from point p to triangle (a, b, c), model units.
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// Largest distance from the vertices and triangle centroids of `from` to the surface of `to`
/// (exact, with the triangles of `to` in a uniform grid); infinity when `to` has no triangle.
double one_sided_distance(const TriangleMesh& from, const TriangleMesh& to);

/// max(one_sided_distance(a, b), one_sided_distance(b, a)).
double hausdorff_distance(const TriangleMesh& a, const TriangleMesh& b);

}  // namespace dg::test
