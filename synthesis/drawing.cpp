#include "synthesis/drawing.h"

#include <algorithm>
#include <limits>

namespace dg {

PageFrame page_frame(const Drawing& drawing, double margin_fraction) {
  Vec2 low = Vec2::Constant(std::numeric_limits<double>::infinity());
  Vec2 high = -low;
  for (const Stroke& stroke : drawing.strokes) add_path_bounds(stroke.path, low, high);
  if (!(low.x() <= high.x())) low = high = Vec2::Zero();
  const Vec2 size = high - low;
  const double margin = size.maxCoeff() > 0 ? size.maxCoeff() * margin_fraction : 1.0;
  PageFrame frame;
  frame.low = low - Vec2::Constant(margin);
  frame.width = size.x() + 2 * margin;
  frame.height = size.y() + 2 * margin;
  return frame;
}

}  // namespace dg
