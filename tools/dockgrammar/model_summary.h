#pragma once
// Human-readable and JSON summaries of a prepared model.

#include "geometry/prepared_model.h"

#include <nlohmann/json.hpp>

#include <string>

namespace dg::cli {

/// Aligned text report: cleaning, r/eps, voxel surface, a point cloud's sampling (spacing and
/// scatter, see PreparedModel::cloud_sampling) or a mesh's feature lines, timings.
std::string summary_text(const PreparedModel& prepared);

/// The same as JSON: {model, cleaning, materials, match_materials, material_groups (arrays of
/// names), origin (PreparedModel::origin), r, eps, voxel_surface, feature_lines, cloud_sampling (null for a mesh, else {spacing,
/// noise, noise_wide}, model units), timings_s}.
nlohmann::json summary_json(const PreparedModel& prepared);

/// "(x, y, z)" with `digits` significant digits, more where a component reaches 10^5 and more
/// (survey coordinates keep three places more than their whole digits: 412351.67, 5678901.23).
std::string coordinates_text(const Vec3& v, int digits);

/// coordinates_text of a fitted direction, motion or point: components within `noise` (model
/// units) or 1e-6 of the vector's length of 0 (the detector's rounding noise, far under the
/// digits shown) and -0 show as 0.
std::string fitted_vector_text(const Vec3& v, int digits, double noise = 0.0);

/// [x, y, z] as JSON.
nlohmann::json coordinates_json(const Vec3& v);

/// One sentence saying the model was analysed moved near the origin (PreparedModel::origin) and
/// what that means for the outputs; empty when it was not moved.
std::string origin_text(const PreparedModel& prepared);

/// The materials' names as a JSON array, in index order.
nlohmann::json material_names(const std::vector<Material>& materials);

/// The groups of materials that match one another (classes of two or more materials, see
/// PreparedModel::material_classes), each as its material names in model order.
std::vector<std::vector<std::string>> material_groups(const PreparedModel& prepared);

}  // namespace dg::cli
