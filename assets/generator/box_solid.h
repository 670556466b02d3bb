#pragma once
// Solids made of axis-aligned boxes added and subtracted in order, turned into ONE closed,
// outward-oriented surface without overlapping parts or T-junctions: all box faces live on a
// common grid of coordinate planes and the surface is the boundary of the occupied grid cells.

#include "geometry/mesh.h"

#include <array>
#include <vector>

namespace dg::assets {

/// One box operation in model units; `subtract` carves the box out of what is there so far.
struct BoxOp {
  Vec3 min;
  Vec3 max;
  bool subtract = false;
};

/// Boxes applied in order, plus seam planes (coordinate values per axis) that only split faces,
/// e.g. at the borders between repeated units so every triangle lies inside one unit.
struct BoxSolid {
  std::vector<BoxOp> ops;
  std::array<std::vector<double>, 3> seams;
};

/// Unions the box [min, max] into the solid.
void add_box(BoxSolid& solid, const Vec3& min, const Vec3& max);
/// Carves the box [min, max] out of the solid.
void subtract_box(BoxSolid& solid, const Vec3& min, const Vec3& max);
/// Adds a seam plane `axis` = value (0 = x, 1 = y, 2 = z).
void add_seam(BoxSolid& solid, int axis, double value);

/// The boundary surface of the solid. Coordinates closer than 1e-9 (relative to the extent)
/// are one plane. Every grid face is split into detail x detail quads, each into two triangles
/// (so the triangle count grows with detail^2 and the shape stays the same). Shapes where two
/// cells touch only along an edge give non-manifold edges; the models avoid them.
TriangleMesh box_solid_surface(const BoxSolid& solid, int detail);

}  // namespace dg::assets
