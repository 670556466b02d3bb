#pragma once
// Option checks for numbers with short messages that name the option, the range and the value
// (CLI11's own print ranges up to DBL_MAX and say "not in range" for a word).

#include <CLI/CLI.hpp>

#include <fmt/core.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <concepts>
#include <limits>
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

/// Accepts a number from `lowest` to `highest` (a whole number for an integral T); otherwise a
/// usage error naming the range and the value ("expected a whole number from 1 to 1000000, got
/// 'x'"; "... 0 or more ..." when `highest` is T's largest value).
template <typename T>
CLI::Validator number_in(T lowest, T highest) {
  const std::string kind = std::integral<T> ? "a whole number" : "a number";
  const std::string range = highest == std::numeric_limits<T>::max() ? fmt::format("{} or more", lowest)
                                                                      : fmt::format("from {} to {}", lowest, highest);
  return CLI::Validator(
      [=](std::string& input) -> std::string {
        T value{};
        bool number = false;
        if constexpr (std::integral<T>) {  // whole string, no sign on unsigned, no overflow
          const char* end = input.data() + input.size();
          const auto [stop, error] = std::from_chars(input.data(), end, value);
          number = error == std::errc() && stop == end;
        } else {
          number = CLI::detail::lexical_cast(input, value) && std::isfinite(value);
        }
        if (number && value >= lowest && value <= highest) return {};
        return "expected " + kind + " " + range + ", got '" + input + "'";
      },
      highest == std::numeric_limits<T>::max() ? fmt::format(">= {}", lowest) : fmt::format("[{}, {}]", lowest, highest));
}

/// A seed: any whole number from 0 to 2^64 - 1.
inline CLI::Validator seed_number() { return number_in<std::uint64_t>(0, std::numeric_limits<std::uint64_t>::max()); }

}  // namespace dg::cli
