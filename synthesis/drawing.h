#pragma once
// A 2D drawing made by the turtle: strokes in y-up drawing units.

#include "geometry/image.h"
#include "synthesis/path2d.h"

#include <cstddef>
#include <vector>

namespace dg {

/// One drawn element: a segment (drawing symbol) or a placed motif copy, and the index of the
/// module in the derived string that made it; colour and a width factor (times the picture's
/// line width) for pictures that mix kinds of strokes (e.g. guides under grown structure).
struct Stroke {
  Path2d path;
  std::size_t module_index = 0;
  Rgba8 color{0, 0, 0, 255};
  double width_factor = 1;
};

/// Strokes in derivation order, in y-up turtle coordinates.
struct Drawing {
  std::vector<Stroke> strokes;
};

/// The page a drawing is shown on: its bounding box grown by a margin. Page coordinates have
/// their origin at the top-left corner and y pointing down (as in SVG).
struct PageFrame {
  Vec2 low = Vec2::Zero();   ///< y-up drawing coordinates of the page's bottom-left corner
  double width = 1;          ///< page size in drawing units
  double height = 1;

  /// Page coordinates (y down) of the drawing point p (y up).
  Vec2 to_page(const Vec2& p) const { return Vec2(p.x() - low.x(), low.y() + height - p.y()); }
};

/// The frame around all strokes with `margin_fraction` of the longer side added on every side
/// (a margin of 1 unit when the drawing has no extent, so it still has a page).
PageFrame page_frame(const Drawing& drawing, double margin_fraction);

}  // namespace dg
