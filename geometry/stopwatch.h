#pragma once
// Wall-clock timing of consecutive stages.

#include <chrono>

namespace dg {

/// Measures stages one after another: lap() returns the seconds since construction or the
/// previous lap().
class Stopwatch {
 public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - start_).count();
    start_ = now;
    return seconds;
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace dg
