#pragma once
// Binarization and thinning of line drawings: ink pixels by Otsu's threshold on the luminance
// (over a white background), then a one-pixel-wide skeleton by Zhang–Suen thinning.

#include "geometry/image.h"

#include <cstdint>
#include <vector>

namespace dg {

/// A binary raster, row-major, top row first; 1 = ink.
struct BinaryImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> ink;

  /// Ink at (x, y); false outside the raster.
  bool at(int x, int y) const {
    return x >= 0 && y >= 0 && x < width && y < height && ink[static_cast<std::size_t>(y) * width + x] != 0;
  }
};

/// Luminance in [0, 255] of each pixel composited over white (Rec. 601 weights).
std::vector<double> luminance_over_white(const Image& image);

/// Otsu's threshold of a luminance histogram (256 bins): the level that maximizes the
/// between-class variance. Values below it are ink.
double otsu_threshold(const std::vector<double>& luminance);

/// Ink where the luminance is below the level halfway between Otsu's threshold and the lightest
/// pixel (dark strokes on a light background; thin anti-aliased lines stay connected).
/// An image of one tone has no ink.
BinaryImage binarize(const Image& image);

/// Zhang–Suen thinning (1984) until no pixel changes, then removal of staircase pixels whose
/// two 4-neighbours on a corner are linked diagonally anyway; keeps 8-connectivity.
BinaryImage thin(const BinaryImage& binary);

}  // namespace dg
