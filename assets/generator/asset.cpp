#include "assets/generator/asset.h"

#include "assets/generator/models.h"
#include "geometry/errors.h"

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

}  // namespace dg::assets
