#pragma once
// Exact overlap test of triangles (and, as degenerate triangles, segments) against closed boxes.

#include "geometry/types.h"

namespace dg {

/// True when triangle (a, b, c) and the CLOSED box [lo, hi] share at least one point
/// (touching at an edge or corner counts, up to a margin of 1e-10 of the coordinates' size that
/// absorbs rounding). Separating-axis test over the 13 axes
/// (3 box normals, the triangle normal, 9 edge cross products). A segment [a, b] is tested
/// exactly as the degenerate triangle (a, b, b): its zero normal never separates and the
/// remaining axes are the complete set for a segment.
bool triangle_box_overlap(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& lo, const Vec3& hi);

}  // namespace dg
