#pragma once
// Parametric exemplar models with exact ground truth (repetitions, counts, areas), so every
// later stage (symmetry, grammar, resize) has a known right answer.

#include "geometry/mesh.h"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace dg::assets {

/// A generated model: a short name (e.g. "fence_4"), its mesh (metres) and its ground truth.
/// ground_truth holds "generator", "parameters" (all, defaults filled in), "units",
/// "triangle_count", "vertex_count", "surface_area", "bounding_box", "repetitions" (see
/// repetition.h), "grids" (pairs of repetitions forming a 2-grid) and model-specific notes.
struct Asset {
  std::string name;
  TriangleMesh mesh;
  nlohmann::json ground_truth;
};

/// Builds the model `name` (one of asset_names()) from a JSON object of parameters; missing
/// parameters take their documented defaults. Throws InputError for an unknown name, an
/// unknown parameter or a value out of range.
Asset make_asset(const std::string& name, const nlohmann::json& params);

/// Builds `name` with the detail that brings its triangle count closest to `target_triangles`:
/// detail round(sqrt(N / T1)), T1 = the count at detail 1 (counts grow about with detail^2).
/// A "detail" entry in `params` is replaced.
Asset make_asset_with_triangles(const std::string& name, nlohmann::json params, std::size_t target_triangles);

/// Names accepted by make_asset, in a fixed order.
std::vector<std::string> asset_names();

}  // namespace dg::assets
