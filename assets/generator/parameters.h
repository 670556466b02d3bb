#pragma once
// Reading a model's parameters from JSON: defaults for missing keys, range checks, and a clear
// InputError for unknown keys or bad values.

#include <nlohmann/json.hpp>

#include <string>

namespace dg::assets {

/// The parameters given for one model and the full set actually used (given or defaulted).
struct Parameters {
  std::string model;       ///< model name, for messages
  nlohmann::json given;    ///< object as passed by the caller
  nlohmann::json used;     ///< every parameter the model read, with its value
};

/// Starts reading `given` (must be a JSON object or null) for `model`.
Parameters read_parameters(const std::string& model, const nlohmann::json& given);
/// Integer parameter `key` in [min, max], `fallback` when absent.
int integer_parameter(Parameters& parameters, const std::string& key, int fallback, int min, int max);
/// Real parameter `key` in [min, max] (model units, usually metres), `fallback` when absent.
double number_parameter(Parameters& parameters, const std::string& key, double fallback, double min, double max);
/// Throws InputError when `given` holds a key the model never read.
void reject_unknown_parameters(const Parameters& parameters);

}  // namespace dg::assets
