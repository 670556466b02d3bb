#include "geometry/skeleton.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace dg {

namespace {

// The 8 neighbours P2..P9 of Zhang–Suen, clockwise from north.
std::array<int, 8> neighbours(const BinaryImage& b, int x, int y) {
  return {b.at(x, y - 1), b.at(x + 1, y - 1), b.at(x + 1, y), b.at(x + 1, y + 1),
          b.at(x, y + 1), b.at(x - 1, y + 1), b.at(x - 1, y), b.at(x - 1, y - 1)};
}

int transitions(const std::array<int, 8>& p) {
  int count = 0;
  for (int k = 0; k < 8; ++k) count += p[k] == 0 && p[(k + 1) % 8] == 1;
  return count;
}

}  // namespace

std::vector<double> luminance_over_white(const Image& image) {
  std::vector<double> values;
  values.reserve(image.pixels.size());
  for (const Rgba8& p : image.pixels) {
    const double alpha = p.a / 255.0;
    const double y = 0.299 * p.r + 0.587 * p.g + 0.114 * p.b;
    values.push_back(alpha * y + (1 - alpha) * 255);
  }
  return values;
}

double otsu_threshold(const std::vector<double>& luminance) {
  std::array<double, 256> histogram{};
  for (double v : luminance) histogram[static_cast<std::size_t>(std::clamp(std::lround(v), 0L, 255L))] += 1;
  const double total = static_cast<double>(luminance.size());
  double sum = 0;
  for (int k = 0; k < 256; ++k) sum += k * histogram[k];
  double below = 0, sum_below = 0, best = -1, threshold = 128;
  for (int k = 0; k < 256; ++k) {
    below += histogram[k];
    sum_below += k * histogram[k];
    const double above = total - below;
    if (below == 0 || above == 0) continue;
    const double mean_below = sum_below / below, mean_above = (sum - sum_below) / above;
    const double variance = below * above * (mean_below - mean_above) * (mean_below - mean_above);
    if (variance > best) {
      best = variance;
      threshold = k + 0.5;  // levels up to k are ink
    }
  }
  return threshold;
}

BinaryImage binarize(const Image& image) {
  BinaryImage b{image.width, image.height, std::vector<std::uint8_t>(image.pixels.size(), 0)};
  const std::vector<double> luminance = luminance_over_white(image);
  if (luminance.empty()) return b;
  const auto [low, high] = std::minmax_element(luminance.begin(), luminance.end());
  if (*high - *low < 1) return b;
  // Halfway between Otsu's level and the paper, so faint anti-aliased diagonals stay connected.
  const double threshold = 0.5 * (otsu_threshold(luminance) + *high);
  for (std::size_t k = 0; k < luminance.size(); ++k) b.ink[k] = luminance[k] < threshold;
  return b;
}

BinaryImage thin(const BinaryImage& binary) {
  BinaryImage b = binary;
  std::vector<std::size_t> remove;
  for (bool changed = true; changed;) {
    changed = false;
    for (int pass = 0; pass < 2; ++pass) {
      remove.clear();
      for (int y = 0; y < b.height; ++y)
        for (int x = 0; x < b.width; ++x) {
          if (!b.at(x, y)) continue;
          const auto p = neighbours(b, x, y);
          const int count = std::accumulate(p.begin(), p.end(), 0);
          if (count < 2 || count > 6 || transitions(p) != 1) continue;
          // P2 P4 P6 / P4 P6 P8 in the first pass, P2 P4 P8 / P2 P6 P8 in the second.
          const bool a = pass == 0 ? !(p[0] && p[2] && p[4]) : !(p[0] && p[2] && p[6]);
          const bool c = pass == 0 ? !(p[2] && p[4] && p[6]) : !(p[0] && p[4] && p[6]);
          if (a && c) remove.push_back(static_cast<std::size_t>(y) * b.width + x);
        }
      for (std::size_t k : remove) b.ink[k] = 0;
      changed = changed || !remove.empty();
    }
  }
  // Staircase pixels: a corner pixel whose two 4-neighbours (e.g. north and east) are on while
  // the pixel between them (north-east) is off, and that has no other neighbour, is redundant.
  for (int y = 0; y < b.height; ++y)
    for (int x = 0; x < b.width; ++x) {
      if (!b.at(x, y)) continue;
      const auto p = neighbours(b, x, y);
      if (std::accumulate(p.begin(), p.end(), 0) != 2) continue;
      for (int k = 0; k < 8; k += 2)
        if (p[k] && p[(k + 2) % 8]) b.ink[static_cast<std::size_t>(y) * b.width + x] = 0;
    }
  return b;
}

}  // namespace dg
