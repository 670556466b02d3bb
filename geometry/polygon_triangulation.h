#pragma once
// Triangles of one planar (or nearly planar) polygon given by corner indices, staying inside it:
// model files carry non-convex n-gons (a floor notched around column plinths) whose fan from the
// first corner would cover what lies outside them.

#include "geometry/types.h"

#include <cstdint>
#include <span>
#include <vector>

namespace dg {

/// The fan (c0 c1 c2), (c0 c2 c3), ... of a polygon's corners: n - 2 triangles.
std::vector<Triangle> fan(std::span<const std::uint32_t> corners);

/// The polygon's n - 2 triangles, in its winding order: its fan (c0 c1 c2), (c0 c2 c3), ... when
/// it is convex; else ear clipping in the plane of its Newell normal, started from its lowest
/// corner by position (so a back-to-back copy, its corners in the opposite order, gets the same
/// triangles turned over). Degenerate polygons (no normal, non-finite positions) and polygons of
/// more than kMaxClippedCorners corners keep their fan; a self-intersecting polygon is clipped
/// as far as ears exist, then at its most convex corner.
std::vector<Triangle> triangulate_polygon(const std::vector<Vec3>& positions, std::span<const std::uint32_t> corners);

/// Ear clipping is quadratic to cubic in the corners: larger polygons keep their fan.
inline constexpr std::size_t kMaxClippedCorners = 4096;

}  // namespace dg
