#include "geometry/depth_raster.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace dg {

namespace {

constexpr std::int64_t one = 256;  // fixed-point units per pixel
constexpr std::int64_t half = one / 2;
constexpr int band_rows = 16;  // rows per parallel work item
constexpr double coordinate_limit = 4194304.0;  // 2^22 pixels keeps edge functions inside int64

// Floor of a / b for b > 0.
std::int64_t floor_div(std::int64_t a, std::int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

// A projected corner in fixed-point pixel coordinates; invalid when not finite or too far out.
struct FixedPoint {
  std::int64_t x = 0, y = 0;
  double key = 0;
  bool valid = false;
};

FixedPoint to_fixed(const Vec3& p) {
  if (!(std::abs(p.x()) < coordinate_limit && std::abs(p.y()) < coordinate_limit && std::isfinite(p.z()))) return {};
  return {std::llround(p.x() * one), std::llround(p.y() * one), p.z(), true};
}

// A triangle in fixed-point pixel coordinates, wound so that its doubled area is positive.
struct FixedTriangle {
  std::array<std::int64_t, 3> x, y;
  std::array<double, 3> key;
  std::int64_t area;
  // Inclusive sample ranges whose centres can lie inside.
  int column_begin, column_end, row_begin, row_end;
};

// Sets up triangle t; false when it is degenerate, has an invalid corner, or covers no sample
// centre of the frame.
bool set_up(const std::vector<FixedPoint>& points, const Triangle& t, int width, int height, FixedTriangle& out) {
  for (int i = 0; i < 3; ++i) {
    const FixedPoint& p = points[t[i]];
    if (!p.valid) return false;
    out.x[i] = p.x;
    out.y[i] = p.y;
    out.key[i] = p.key;
  }
  out.area = (out.x[1] - out.x[0]) * (out.y[2] - out.y[0]) - (out.y[1] - out.y[0]) * (out.x[2] - out.x[0]);
  if (out.area == 0) return false;
  if (out.area < 0) {
    std::swap(out.x[1], out.x[2]);
    std::swap(out.y[1], out.y[2]);
    std::swap(out.key[1], out.key[2]);
    out.area = -out.area;
  }
  const auto [x_low, x_high] = std::minmax({out.x[0], out.x[1], out.x[2]});
  const auto [y_low, y_high] = std::minmax({out.y[0], out.y[1], out.y[2]});
  // Sample centre of column i is i * one + half.
  out.column_begin = static_cast<int>(std::max<std::int64_t>(0, floor_div(x_low - half + one - 1, one)));
  out.column_end = static_cast<int>(std::min<std::int64_t>(width - 1, floor_div(x_high - half, one)));
  out.row_begin = static_cast<int>(std::max<std::int64_t>(0, floor_div(y_low - half + one - 1, one)));
  out.row_end = static_cast<int>(std::min<std::int64_t>(height - 1, floor_div(y_high - half, one)));
  return out.column_begin <= out.column_end && out.row_begin <= out.row_end;
}

// value(p) = a * p.x + b * p.y + c: twice the signed area of (from, to, p), positive on the
// triangle's inner side. `bias` is 0 when samples exactly on the edge belong to this triangle
// and -1 otherwise; of two opposite edge directions exactly one owns its samples.
struct EdgeFunction {
  std::int64_t a, b, c, bias;

  EdgeFunction(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1)
      : a(y0 - y1), b(x1 - x0), c((y1 - y0) * x0 - (x1 - x0) * y0),
        bias((y1 > y0 || (y1 == y0 && x1 < x0)) ? 0 : -1) {}
  std::int64_t at(std::int64_t x, std::int64_t y) const { return a * x + b * y + c; }
};

// Range [first, last] of steps k >= 0 with value + k * step >= 0 (last = max_k when unbounded).
void clip_steps(std::int64_t value, std::int64_t step, std::int64_t& first, std::int64_t& last) {
  if (step > 0) {
    if (value < 0) first = std::max(first, (-value + step - 1) / step);
  } else if (step < 0) {
    last = value < 0 ? -1 : std::min(last, value / -step);
  } else if (value < 0) {
    last = -1;
  }
}

// Draws triangle f into the rows [row_begin, row_end] of the raster. Per row only the span of
// columns where all three (biased) edge functions are non-negative is visited; it is solved
// exactly in integers, so thin triangles with large bounding boxes stay cheap.
void draw(const FixedTriangle& f, std::uint32_t index, int row_begin, int row_end, DepthRaster& raster) {
  const EdgeFunction e0(f.x[1], f.y[1], f.x[2], f.y[2]);
  const EdgeFunction e1(f.x[2], f.y[2], f.x[0], f.y[0]);
  const EdgeFunction e2(f.x[0], f.y[0], f.x[1], f.y[1]);
  const double inverse_area = 1.0 / static_cast<double>(f.area);
  const std::int64_t x_start = f.column_begin * one + half;
  for (int row = std::max(row_begin, f.row_begin); row <= std::min(row_end, f.row_end); ++row) {
    const std::int64_t y = row * one + half;
    std::int64_t w0 = e0.at(x_start, y), w1 = e1.at(x_start, y), w2 = e2.at(x_start, y);
    std::int64_t first = 0, last = f.column_end - f.column_begin;
    clip_steps(w0 + e0.bias, e0.a * one, first, last);
    clip_steps(w1 + e1.bias, e1.a * one, first, last);
    clip_steps(w2 + e2.bias, e2.a * one, first, last);
    if (first > last) continue;
    w0 += first * e0.a * one;
    w1 += first * e1.a * one;
    w2 += first * e2.a * one;
    std::size_t i = raster.index(f.column_begin + static_cast<int>(first), row);
    for (std::int64_t k = first; k <= last; ++k, ++i) {
      const auto key = static_cast<float>(
          (static_cast<double>(w0) * f.key[0] + static_cast<double>(w1) * f.key[1] + static_cast<double>(w2) * f.key[2]) *
          inverse_area);
      if (key > raster.key[i]) {
        raster.key[i] = key;
        raster.triangle[i] = index;
      }
      w0 += e0.a * one;
      w1 += e1.a * one;
      w2 += e2.a * one;
    }
  }
}

}  // namespace

DepthRaster rasterize_depth(const std::vector<Vec3>& projected, const std::vector<Triangle>& triangles, int width,
                            int height) {
  DepthRaster raster;
  raster.width = std::max(width, 0);
  raster.height = std::max(height, 0);
  const std::size_t samples = static_cast<std::size_t>(raster.width) * static_cast<std::size_t>(raster.height);
  raster.key.assign(samples, -std::numeric_limits<float>::infinity());
  raster.triangle.assign(samples, DepthRaster::none);
  if (samples == 0) return raster;

  std::vector<FixedPoint> points(projected.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 4096), [&](const auto& range) {
    for (std::size_t v = range.begin(); v < range.end(); ++v) points[v] = to_fixed(projected[v]);
  });

  // Bin triangles by band of rows (compressed rows: band b holds bin[start[b] .. start[b+1])),
  // in ascending triangle order so that each band draws them in the same order as a serial loop.
  const int bands = (raster.height + band_rows - 1) / band_rows;
  std::vector<std::array<int, 2>> band_range(triangles.size());  // first, last band; first > last: none
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, triangles.size(), 4096), [&](const auto& range) {
    FixedTriangle f;
    for (std::size_t t = range.begin(); t < range.end(); ++t)
      band_range[t] = set_up(points, triangles[t], raster.width, raster.height, f)
                          ? std::array<int, 2>{f.row_begin / band_rows, f.row_end / band_rows}
                          : std::array<int, 2>{1, 0};
  });
  std::vector<std::size_t> start(static_cast<std::size_t>(bands) + 1, 0);
  for (const auto& [first, last] : band_range)
    for (int b = first; b <= last; ++b) ++start[static_cast<std::size_t>(b) + 1];
  for (int b = 0; b < bands; ++b) start[b + 1] += start[b];
  std::vector<std::uint32_t> bin(start.back());
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int b = band_range[t][0]; b <= band_range[t][1]; ++b) bin[fill[b]++] = static_cast<std::uint32_t>(t);

  tbb::parallel_for(0, bands, [&](int b) {
    const int row_begin = b * band_rows;
    const int row_end = std::min(raster.height, row_begin + band_rows) - 1;
    FixedTriangle f;
    for (std::size_t i = start[b]; i < start[b + 1]; ++i)
      if (set_up(points, triangles[bin[i]], raster.width, raster.height, f)) draw(f, bin[i], row_begin, row_end, raster);
  });
  return raster;
}

}  // namespace dg
