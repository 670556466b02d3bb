#pragma once
// Z-buffered triangle rasterization: which triangle is nearest at every sample of a frame.

#include "geometry/types.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace dg {

/// The nearest triangle per sample, row-major, top row first. Sample (x, y) sits at the pixel
/// centre (x + 0.5, y + 0.5).
struct DepthRaster {
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

  int width = 0;
  int height = 0;
  std::vector<float> key;                ///< nearness key of the nearest triangle (larger = nearer); -inf when empty
  std::vector<std::uint32_t> triangle;   ///< index of the nearest triangle, or `none`

  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }
};

/// Rasterizes `triangles` whose corners are `projected[i] = (pixel x, pixel y, key)` (key affine
/// in pixel coordinates, larger = nearer, e.g. Camera::project) into a width x height frame.
/// Both windings are drawn; a sample on an edge shared by two triangles belongs to exactly one
/// of them (fixed-point edge functions with 1/256 pixel precision and a tie-break rule), so
/// closed meshes show no cracks. At equal keys the lower triangle index wins. Triangles with a
/// non-finite corner are skipped. Runs in parallel over bands of rows; the result does not
/// depend on the number of threads. Corner indices must be valid; pixel coordinates must lie
/// within +-2^22 of the frame.
DepthRaster rasterize_depth(const std::vector<Vec3>& projected, const std::vector<Triangle>& triangles, int width,
                            int height);

}  // namespace dg
