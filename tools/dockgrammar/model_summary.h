#pragma once
// Human-readable and JSON summaries of a prepared model.

#include "geometry/prepared_model.h"

#include <nlohmann/json.hpp>

#include <string>

namespace dg::cli {

/// Aligned text report: cleaning, r/eps, voxel surface, feature lines, timings.
std::string summary_text(const PreparedModel& prepared);

/// The same as JSON: {model, cleaning, materials, r, eps, voxel_surface, feature_lines, timings_s}.
nlohmann::json summary_json(const PreparedModel& prepared);

/// The materials' names as a JSON array, in index order.
nlohmann::json material_names(const std::vector<Material>& materials);

}  // namespace dg::cli
