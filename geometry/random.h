#pragma once
// Seeded random numbers that are the same with every standard library: std::mt19937_64 is
// specified exactly, and its bits are mapped to doubles here (not by std::uniform_*_distribution,
// whose output differs between implementations).

#include <cstdint>
#include <random>

namespace dg {

/// A reproducible random stream: the same seed gives the same numbers everywhere.
struct Random {
  explicit Random(std::uint64_t seed) : engine(seed) {}

  /// Uniform double in [0, 1) from the top 53 bits of one draw.
  double uniform() { return static_cast<double>(engine() >> 11) * 0x1.0p-53; }
  /// Uniform double in [low, high).
  double uniform(double low, double high) { return low + (high - low) * uniform(); }

  std::mt19937_64 engine;
};

}  // namespace dg
