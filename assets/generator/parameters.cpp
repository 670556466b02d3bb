#include "assets/generator/parameters.h"

#include "geometry/errors.h"

#include <cmath>
#include <optional>
#include <fmt/format.h>

namespace dg::assets {

namespace {

/// The value of `key` as a finite number, or nullopt when absent.
std::optional<double> given_number(const Parameters& parameters, const std::string& key) {
  if (!parameters.given.contains(key)) return std::nullopt;
  const nlohmann::json& value = parameters.given.at(key);
  if (!value.is_number()) {
    throw InputError(fmt::format("{}: parameter '{}' must be a number, got {}", parameters.model, key, value.dump()));
  }
  const double number = value.get<double>();
  if (!std::isfinite(number)) throw InputError(fmt::format("{}: parameter '{}' is not finite", parameters.model, key));
  return number;
}

}  // namespace

Parameters read_parameters(const std::string& model, const nlohmann::json& given) {
  if (!given.is_null() && !given.is_object()) {
    throw InputError(fmt::format("{}: parameters must be a JSON object, got {}", model, given.dump()));
  }
  return Parameters{model, given.is_null() ? nlohmann::json::object() : given, nlohmann::json::object()};
}

int integer_parameter(Parameters& parameters, const std::string& key, int fallback, int min, int max) {
  int value = fallback;
  if (const auto number = given_number(parameters, key)) {
    if (*number != std::floor(*number)) {
      throw InputError(fmt::format("{}: parameter '{}' must be an integer, got {}", parameters.model, key, *number));
    }
    if (*number < min || *number > max) {
      throw InputError(fmt::format("{}: parameter '{}' must be in [{}, {}], got {}", parameters.model, key, min, max, *number));
    }
    value = static_cast<int>(*number);
  }
  parameters.used[key] = value;
  return value;
}

double number_parameter(Parameters& parameters, const std::string& key, double fallback, double min, double max) {
  double value = fallback;
  if (const auto number = given_number(parameters, key)) {
    if (*number < min || *number > max) {
      throw InputError(fmt::format("{}: parameter '{}' must be in [{}, {}], got {}", parameters.model, key, min, max, *number));
    }
    value = *number;
  }
  parameters.used[key] = value;
  return value;
}

void reject_unknown_parameters(const Parameters& parameters) {
  for (const auto& [key, value] : parameters.given.items()) {
    if (!parameters.used.contains(key)) {
      std::string known;
      for (const auto& [name, ignored] : parameters.used.items()) known += (known.empty() ? "" : ", ") + name;
      throw InputError(fmt::format("{}: unknown parameter '{}' (known: {})", parameters.model, key, known));
    }
  }
}

}  // namespace dg::assets
