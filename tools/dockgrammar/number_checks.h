#pragma once
// Option checks for numbers with short messages (CLI11's own print their range up to DBL_MAX).

#include <CLI/CLI.hpp>

#include <cmath>
#include <string>

namespace dg::cli {

/// Accepts a finite number >= 0 (`positive`: > 0); otherwise a usage error naming the value.
/// Use non_negative_number() or positive_number().
inline CLI::Validator finite_number_check(bool positive) {
  return CLI::Validator(
      [positive](std::string& input) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(input, value) || !std::isfinite(value)) return "'" + input + "' is not a finite number";
        if (positive ? value > 0.0 : value >= 0.0) return {};
        return "must be " + std::string(positive ? "greater than 0" : "0 or more") + ", got " + input;
      },
      positive ? "POSITIVE" : "NONNEGATIVE");
}

/// A finite number >= 0.
inline CLI::Validator non_negative_number() { return finite_number_check(false); }

/// A finite number > 0.
inline CLI::Validator positive_number() { return finite_number_check(true); }

}  // namespace dg::cli
