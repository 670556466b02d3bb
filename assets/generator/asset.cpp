#include "assets/generator/asset.h"

#include "assets/generator/models.h"
#include "geometry/errors.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace dg::assets {

namespace {

using Maker = Asset (*)(const nlohmann::json&);

/// Every model by name, in the order asset_names() reports them.
const std::vector<std::pair<std::string, Maker>>& makers() {
  static const std::vector<std::pair<std::string, Maker>> table = {
      {"fence", make_fence},         {"facade", make_facade},     {"messy_facade", make_messy_facade},
      {"shelf", make_shelf},         {"pipe_tree", make_pipe_tree}, {"spiral_stairs", make_spiral_stairs},
      {"gear", make_gear}};
  return table;
}

}  // namespace

Asset make_asset(const std::string& name, const nlohmann::json& params) {
  for (const auto& [known, maker] : makers()) {
    if (known == name) return maker(params);
  }
  std::string names;
  for (const std::string& known : asset_names()) names += (names.empty() ? "" : ", ") + known;
  throw InputError("unknown model '" + name + "' (known: " + names + ")");
}

std::vector<std::string> asset_names() {
  std::vector<std::string> names;
  for (const auto& entry : makers()) names.push_back(entry.first);
  return names;
}

Asset make_asset_with_triangles(const std::string& name, nlohmann::json params, std::size_t target_triangles) {
  params.erase("detail");
  Asset asset = make_asset(name, params);
  const double base = static_cast<double>(asset.mesh.triangles.size());
  const int detail = std::max(1, static_cast<int>(std::lround(std::sqrt(static_cast<double>(target_triangles) / base))));
  if (detail == 1) return asset;
  params["detail"] = detail;
  return make_asset(name, params);
}

}  // namespace dg::assets
