#pragma once
// Points that split a segment into equal parts, with the end points returned exactly, so that
// neighbouring faces computing the same split from either side get bit-identical vertices.

#include "geometry/types.h"

namespace dg::assets {

/// a + (b - a) * i / parts; exactly a for i == 0 and exactly b for i == parts.
inline double split_value(double a, double b, int i, int parts) {
  if (i == 0) return a;
  if (i == parts) return b;
  return a + (b - a) * i / parts;
}

/// The 2D point version of split_value.
inline Vec2 split_point(const Vec2& a, const Vec2& b, int i, int parts) {
  return Vec2(split_value(a.x(), b.x(), i, parts), split_value(a.y(), b.y(), i, parts));
}

/// Lifts a 2D point to height z.
inline Vec3 at_height(const Vec2& p, double z) { return Vec3(p.x(), p.y(), z); }

}  // namespace dg::assets
