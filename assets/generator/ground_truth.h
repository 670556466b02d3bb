#pragma once
// Assembling the ground-truth record of a generated model.

#include "assets/generator/asset.h"
#include "assets/generator/parameters.h"
#include "assets/generator/repetition.h"

#include <vector>

namespace dg::assets {

/// Triangle and vertex counts, surface area (m^2) and bounding box of a mesh, as JSON.
nlohmann::json mesh_statistics(const TriangleMesh& mesh);

/// A 2-grid made of two repetitions (by name) and the measure of one interior cell.
nlohmann::json grid_json(const Repetition& first, const Repetition& second, const UnitMeasure& cell, const std::string& cell_text);

/// Packs mesh and ground truth into an Asset (mesh statistics computed here).
/// `notes` (an object) is merged into the ground truth (model-specific facts).
Asset finish_asset(const std::string& name, const Parameters& parameters, TriangleMesh mesh,
                   const std::vector<Repetition>& repetitions, const nlohmann::json& grids,
                   const nlohmann::json& notes);

}  // namespace dg::assets
