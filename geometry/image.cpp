#include "geometry/image.h"

#include "geometry/atomic_file.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dg {

namespace {

// Distance from p to the segment [a, b].
double segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

}  // namespace

Image::Image(int width_, int height_, Rgba8 fill)
    : width(std::max(width_, 0)), height(std::max(height_, 0)),
      pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill) {}

void blend_pixel(Image& image, int x, int y, Rgba8 color, double coverage) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height || !(coverage > 0)) return;
  const double alpha = std::min(coverage, 1.0) * color.a / 255.0;
  Rgba8& pixel = image.at(x, y);
  const double below = pixel.a / 255.0 * (1 - alpha);
  const double out = alpha + below;
  auto mix = [&](std::uint8_t source, std::uint8_t destination) {
    const double value = out > 0 ? (source * alpha + destination * below) / out : 0.0;
    return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0, 255.0)));
  };
  pixel = {mix(color.r, pixel.r), mix(color.g, pixel.g), mix(color.b, pixel.b),
           static_cast<std::uint8_t>(std::lround(out * 255.0))};
}

void draw_polyline(Image& image, const std::vector<Vec2>& points, double width, Rgba8 color) {
  if (points.empty() || image.width == 0 || image.height == 0) return;
  const double reach = width / 2 + 0.5;  // coverage falls from 1 to 0 over the last pixel
  Vec2 low = points.front(), high = points.front();
  for (const Vec2& p : points) low = low.cwiseMin(p), high = high.cwiseMax(p);
  if (!low.allFinite() || !high.allFinite()) return;
  const int x0 = std::max(0, static_cast<int>(std::floor(low.x() - reach)));
  const int y0 = std::max(0, static_cast<int>(std::floor(low.y() - reach)));
  const int x1 = std::min(image.width - 1, static_cast<int>(std::ceil(high.x() + reach)));
  const int y1 = std::min(image.height - 1, static_cast<int>(std::ceil(high.y() + reach)));
  if (x0 > x1 || y0 > y1) return;
  const int columns = x1 - x0 + 1;
  std::vector<float> coverage(static_cast<std::size_t>(columns) * static_cast<std::size_t>(y1 - y0 + 1), 0.0f);
  const std::size_t segments = points.size() == 1 ? 1 : points.size() - 1;
  for (std::size_t s = 0; s < segments; ++s) {
    const Vec2& a = points[s];
    const Vec2& b = points[std::min(s + 1, points.size() - 1)];
    const int sx0 = std::max(x0, static_cast<int>(std::floor(std::min(a.x(), b.x()) - reach)));
    const int sy0 = std::max(y0, static_cast<int>(std::floor(std::min(a.y(), b.y()) - reach)));
    const int sx1 = std::min(x1, static_cast<int>(std::ceil(std::max(a.x(), b.x()) + reach)));
    const int sy1 = std::min(y1, static_cast<int>(std::ceil(std::max(a.y(), b.y()) + reach)));
    for (int y = sy0; y <= sy1; ++y)
      for (int x = sx0; x <= sx1; ++x) {
        const double d = segment_distance(Vec2(x + 0.5, y + 0.5), a, b);
        const auto c = static_cast<float>(std::clamp(reach - d, 0.0, 1.0));
        float& slot = coverage[static_cast<std::size_t>(y - y0) * columns + (x - x0)];
        slot = std::max(slot, c);
      }
  }
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x)
      blend_pixel(image, x, y, color, coverage[static_cast<std::size_t>(y - y0) * columns + (x - x0)]);
}

void draw_line(Image& image, const Vec2& a, const Vec2& b, double width, Rgba8 color) {
  draw_polyline(image, {a, b}, width, color);
}

std::vector<unsigned char> encode_png(const Image& image) {
  png_image info{};
  info.version = PNG_IMAGE_VERSION;
  info.width = static_cast<png_uint_32>(image.width);
  info.height = static_cast<png_uint_32>(image.height);
  info.format = PNG_FORMAT_RGBA;
  const auto stride = static_cast<png_int_32>(image.width * 4);
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&info, nullptr, &size, 0, image.pixels.data(), stride, nullptr))
    throw std::runtime_error(std::string("PNG encoding failed: ") + info.message);
  std::vector<unsigned char> bytes(size);
  if (!png_image_write_to_memory(&info, bytes.data(), &size, 0, image.pixels.data(), stride, nullptr))
    throw std::runtime_error(std::string("PNG encoding failed: ") + info.message);
  bytes.resize(size);
  return bytes;
}

void write_png(const std::filesystem::path& path, const Image& image) {
  const std::vector<unsigned char> bytes = encode_png(image);
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  });
}

}  // namespace dg
