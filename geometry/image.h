#pragma once
// A small RGBA raster with anti-aliased drawing and PNG output, for pictures of results
// (2D turtle drawings, views of 3D pieces).

#include "geometry/types.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace dg {

/// One pixel, 8 bits per channel, straight (not premultiplied) alpha.
struct Rgba8 {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;

  friend bool operator==(const Rgba8&, const Rgba8&) = default;
};

static_assert(sizeof(Rgba8) == 4, "pixels are handed to libpng as packed RGBA bytes");

/// Row-major RGBA image, top row first. Pixel (x, y) covers [x, x+1) x [y, y+1) in pixel
/// coordinates, so its center is (x + 0.5, y + 0.5); y grows downward.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<Rgba8> pixels;

  /// An image of width x height pixels filled with `fill`.
  Image(int width, int height, Rgba8 fill);
  /// Pixel at column x, row y (no bounds check).
  Rgba8& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
  const Rgba8& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

/// Composites `color` over pixel (x, y) with the given coverage in [0, 1] (source-over);
/// pixels outside the image are ignored.
void blend_pixel(Image& image, int x, int y, Rgba8 color, double coverage);

/// Draws an anti-aliased polyline of `width` pixels with round joins and caps, in pixel
/// coordinates. Each pixel takes the largest coverage of any of its segments, so joins are not
/// darkened twice. A single point draws a dot.
void draw_polyline(Image& image, const std::vector<Vec2>& points, double width, Rgba8 color);

/// Draws one anti-aliased segment from a to b (pixel coordinates, width in pixels, round caps).
void draw_line(Image& image, const Vec2& a, const Vec2& b, double width, Rgba8 color);

/// PNG file bytes (8-bit RGBA) of `image`; throws std::runtime_error when libpng fails.
std::vector<unsigned char> encode_png(const Image& image);

/// Writes `image` as a PNG file through a temporary file renamed into place.
/// Throws InputError when the file cannot be written.
void write_png(const std::filesystem::path& path, const Image& image);

}  // namespace dg
