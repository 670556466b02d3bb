#include "grammar/material_json.h"

#include "geometry/errors.h"

#include <algorithm>
#include <cmath>

namespace dg {

nlohmann::json materials_json(const std::vector<Material>& materials) {
  nlohmann::json list = nlohmann::json::array();
  for (const Material& m : materials) {
    nlohmann::json entry = {{"name", m.name}, {"diffuse", {m.diffuse.x(), m.diffuse.y(), m.diffuse.z()}}};
    if (m.opacity < 1.0) entry["opacity"] = m.opacity;
    list.push_back(std::move(entry));
  }
  return list;
}

std::vector<Material> read_materials_json(const nlohmann::json& list, const std::string& where) {
  if (!list.is_array()) throw InputError(where + ": \"materials\" must be a list");
  std::vector<Material> materials;
  for (const nlohmann::json& entry : list) {
    const std::string what = where + ": material " + std::to_string(materials.size());
    if (!entry.is_object() || !entry.contains("name") || !entry.at("name").is_string())
      throw InputError(what + " needs a \"name\" text");
    const nlohmann::json& diffuse = entry.contains("diffuse") ? entry.at("diffuse") : nlohmann::json();
    if (!diffuse.is_array() || diffuse.size() != 3 ||
        !std::all_of(diffuse.begin(), diffuse.end(), [](const nlohmann::json& v) { return v.is_number() && std::isfinite(v.get<double>()); }))
      throw InputError(what + " needs \"diffuse\": three finite numbers");
    double opacity = 1.0;
    if (entry.contains("opacity")) {
      const nlohmann::json& value = entry.at("opacity");
      if (!value.is_number() || !(value.get<double>() >= 0.0 && value.get<double>() <= 1.0))
        throw InputError(what + ": \"opacity\" must be a number from 0 to 1");
      opacity = value.get<double>();
    }
    materials.push_back({entry.at("name").get<std::string>(),
                         Vec3(diffuse[0].get<double>(), diffuse[1].get<double>(), diffuse[2].get<double>()), opacity});
  }
  return materials;
}

nlohmann::json material_runs_json(const TriangleMesh& mesh) {
  nlohmann::json runs = nlohmann::json::array();
  std::size_t start = 0;
  for (std::size_t t = 1; t <= mesh.materials.size(); ++t) {
    if (t < mesh.materials.size() && mesh.materials[t] == mesh.materials[start]) continue;
    runs.push_back({mesh.materials[start], t - start});
    start = t;
  }
  return runs;
}

std::vector<std::uint32_t> read_material_runs(const nlohmann::json& runs, std::size_t triangle_count,
                                              std::size_t material_count, const std::string& where) {
  if (!runs.is_array()) throw InputError(where + ": \"material_runs\" must be a list of [material, count] pairs");
  std::vector<std::uint32_t> materials;
  materials.reserve(triangle_count);
  for (const nlohmann::json& run : runs) {
    if (!run.is_array() || run.size() != 2 || !run[0].is_number_unsigned() || !run[1].is_number_unsigned())
      throw InputError(where + ": a material run must be [material, count] (whole numbers)");
    const auto material = run[0].get<std::uint64_t>(), count = run[1].get<std::uint64_t>();
    if (material >= material_count)
      throw InputError(where + ": material run names material " + std::to_string(material) + " of " +
                       std::to_string(material_count));
    if (count > triangle_count - materials.size())
      throw InputError(where + ": material runs cover more than the " + std::to_string(triangle_count) + " triangles");
    materials.insert(materials.end(), count, static_cast<std::uint32_t>(material));
  }
  if (materials.size() != triangle_count)
    throw InputError(where + ": material runs cover " + std::to_string(materials.size()) + " of " +
                     std::to_string(triangle_count) + " triangles");
  return materials;
}

}  // namespace dg
