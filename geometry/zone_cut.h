#pragma once
// Cutting part of a mesh along families of parallel planes (e.g. the voxel planes of a grid
// placed by a rigid motion), keeping the whole mesh conforming: edges shared by two cut
// triangles get one shared vertex per plane, and uncut triangles next to cut ones are split at
// the same vertices, so a closed mesh stays closed.

#include "geometry/mesh.h"

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace dg {

/// Parallel planes direction . x = offsets[i] (direction unit, offsets ascending, model units).
struct PlaneFamily {
  Vec3 direction = Vec3::UnitX();
  std::vector<double> offsets;
};

/// The result of cut_zone: the new mesh (each triangle with the material of the input triangle
/// it lies in, when the input has materials) and, per new triangle, that input triangle.
struct ZoneCut {
  TriangleMesh mesh;
  std::vector<std::uint32_t> origin;
};

/// Decides whether a piece (its three corners, model units) is cut along the plane at `offset`
/// of family `family`.
using PieceFilter = std::function<bool(const std::array<Vec3, 3>& corners, std::size_t family, double offset)>;

/// Splits the triangles of `mesh` flagged in `zone` (one flag per triangle) along the planes
/// of `families`, one family after the other; with `wanted`, only along the planes it accepts
/// for a piece (lowest first; the parts above are asked again). Vertices of flagged triangles within `tolerance` (model units)
/// of a plane are moved onto it. Every triangle and piece is then split at the vertices that
/// cuts of its neighbours created on its edges, so the mesh stays conforming; new vertices
/// within `tolerance` of an earlier vertex of the cut are merged into it (triangles left with a
/// repeated corner go), so no two vertices of one surface share a spot, unless their surfaces face
/// away from each other (vertex normals more than 90 degrees apart: touching parts, such as a
/// leg's top and the seat's underside on it, cut along the same lines, stay apart). Deterministic.
ZoneCut cut_zone(const TriangleMesh& mesh, const std::vector<char>& zone, const std::vector<PlaneFamily>& families,
                 double tolerance, const PieceFilter& wanted = {});

}  // namespace dg
