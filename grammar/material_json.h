#pragma once
// Materials in the grammar file: the model's material list and, per stored mesh, its triangles'
// material indices as runs. Documented in docs/grammar-file.md ("Materials").

#include "geometry/mesh.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace dg {

/// The material list as JSON: [{"name": ..., "diffuse": [r, g, b]}, ...] (linear RGB 0..1), with
/// "opacity" only for a material below 1.
nlohmann::json materials_json(const std::vector<Material>& materials);

/// Reads a material list written by materials_json. Throws InputError (prefixed by `where`)
/// when an entry has no name, no three finite diffuse numbers or an opacity outside 0..1.
std::vector<Material> read_materials_json(const nlohmann::json& list, const std::string& where);

/// The material indices of `mesh`'s triangles as runs in triangle order: [[material, count], ...]
/// (count >= 1; consecutive runs differ in material). `mesh` must carry materials.
nlohmann::json material_runs_json(const TriangleMesh& mesh);

/// Expands runs written by material_runs_json into one index per triangle. Throws InputError
/// (prefixed by `where`) unless the counts add up to `triangle_count` and every index is below
/// `material_count`.
std::vector<std::uint32_t> read_material_runs(const nlohmann::json& runs, std::size_t triangle_count,
                                              std::size_t material_count, const std::string& where);

}  // namespace dg
