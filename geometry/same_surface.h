#pragma once
// Whether two triangle meshes are the same surface up to a tolerance, however they are
// triangulated or layered; and whether two point clouds sample the same surface.

#include "geometry/mesh.h"

namespace dg {

/// True when `a` and `b` have bounding boxes within `tolerance` (model units) and, for each
/// material, surfaces that cover each other on cells of tolerance / 2 (every cell one surface
/// passes through touches one the other passes through, so they lie within about 1.7 tolerance
/// of each other). A material of no more than tolerance^2 of area may be missing from one of
/// them. Area is not compared: a mesh holding a hidden second layer of faces (duplicated
/// triangles, as real assets have) is the same surface. Triangles with a twin in the other mesh
/// (corners within tolerance / 8) need no cells, nor do flat regions (coplanar flat faces, see
/// flat_regions) that have one in the other mesh with the same plane, outline and area within
/// tolerance / 2 (see same_flat_region), however each is triangulated; the rest is sampled, on
/// cells grown to keep to about a million where its area needs more (the test then allows
/// proportionally more).
bool same_surface(const TriangleMesh& a, const TriangleMesh& b, double tolerance);

/// True when `a` and `b` have bounding boxes within 2 `tolerance` (model units) and their points
/// cover each other on cells of edge `tolerance` (every cell one cloud has a point in touches
/// one the other has a point in): two samplings of one surface, at least one point per cell
/// where it passes, within about 3.5 tolerance of each other.
bool same_points(const PointCloud& a, const PointCloud& b, double tolerance);

}  // namespace dg
