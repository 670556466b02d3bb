#pragma once
// Whether two triangle meshes are the same surface up to a tolerance, however they are
// triangulated or layered.

#include "geometry/mesh.h"

namespace dg {

/// True when `a` and `b` have bounding boxes within `tolerance` (model units) and, for each
/// material, surfaces that cover each other on cells of tolerance / 2 (every cell one surface
/// passes through touches one the other passes through, so they lie within about 1.7 tolerance
/// of each other). A material of no more than tolerance^2 of area may be missing from one of
/// them. Area is not compared: a mesh holding a hidden second layer of faces (duplicated
/// triangles, as real assets have) is the same surface.
bool same_surface(const TriangleMesh& a, const TriangleMesh& b, double tolerance);

}  // namespace dg
