#include "synthesis/render.h"

#include "geometry/atomic_file.h"
#include "geometry/errors.h"

#include <algorithm>
#include <cmath>

namespace dg {

namespace {

std::string format_svg_color(const Rgba8& color) {
  static const char* digits = "0123456789abcdef";
  std::string text = "#";
  for (const std::uint8_t channel : {color.r, color.g, color.b}) {
    text += digits[channel >> 4];
    text += digits[channel & 15];
  }
  return text;
}

}  // namespace

std::string format_svg(const Drawing& drawing, const RenderOptions& options) {
  const PageFrame frame = page_frame(drawing, options.margin_fraction);
  const double long_side = std::max(frame.width, frame.height);
  const double stroke_width = options.line_width_px * long_side / std::max(options.long_side_px, 1);
  const int d = options.decimals;
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + format_svg_number(frame.width, d) +
                    "\" height=\"" + format_svg_number(frame.height, d) + "\" viewBox=\"0 0 " +
                    format_svg_number(frame.width, d) + " " + format_svg_number(frame.height, d) +
                    "\" fill=\"none\" stroke=\"black\" stroke-width=\"" + format_svg_number(stroke_width, d + 1) +
                    "\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
  for (const Stroke& stroke : drawing.strokes) {
    const Path2d page = map_path(stroke.path, [&](const Vec2& p) { return frame.to_page(p); });
    svg += "<path d=\"" + format_svg_path(page, d) + "\"";
    if (stroke.color != Rgba8{0, 0, 0, 255}) svg += " stroke=\"" + format_svg_color(stroke.color) + "\"";
    if (stroke.width_factor != 1)
      svg += " stroke-width=\"" + format_svg_number(stroke_width * stroke.width_factor, d + 1) + "\"";
    svg += "/>\n";
  }
  return svg + "</svg>\n";
}

Image rasterize(const Drawing& drawing, const RenderOptions& options) {
  const PageFrame frame = page_frame(drawing, options.margin_fraction);
  const double px_per_unit = std::max(options.long_side_px, 1) / std::max(frame.width, frame.height);
  const int width = std::max(1, static_cast<int>(std::lround(frame.width * px_per_unit)));
  const int height = std::max(1, static_cast<int>(std::lround(frame.height * px_per_unit)));
  Image image(width, height, Rgba8{255, 255, 255, 255});
  for (const Stroke& stroke : drawing.strokes) {
    const Path2d pixels = map_path(stroke.path, [&](const Vec2& p) { return Vec2(frame.to_page(p) * px_per_unit); });
    for (const std::vector<Vec2>& line : flatten_path(pixels, 2.0))
      draw_polyline(image, line, options.line_width_px * stroke.width_factor, stroke.color);
  }
  return image;
}

void write_svg(const std::filesystem::path& path, const Drawing& drawing, const RenderOptions& options) {
  const std::string svg = format_svg(drawing, options);
  write_file_atomically(path, [&](std::ostream& out) { out << svg; }, false);
}

}  // namespace dg
