#include "tools/dockgrammar/up_axis.h"

#include <utility>

namespace dg::cli {

void add_up_option(CLI::App& command, std::string& axis, const std::string& fallback) {
  command.add_option("--up", axis, "Up axis of the model in pictures: x, y or z (default: " + fallback + ")")
      ->check(CLI::IsMember({"x", "y", "z"}));
}

std::string model_up_axis(const std::string& model_path, const std::string& given) {
  if (!given.empty()) return given;
  const std::string extension = lower_extension(model_path);
  return extension == ".gltf" || extension == ".glb" ? "y" : "";
}

UpAxisChoice symmetry_up_axis(const std::string& model_path, const std::string& given, const Model& model,
                              const SymmetryResult& symmetries) {
  if (std::string axis = model_up_axis(model_path, given); !axis.empty()) return {.axis = std::move(axis)};
  if (const std::optional<TurnAxis> turn = coordinate_turn_axis(symmetries))
    return {.axis = std::string(1, "xyz"[turn->axis]), .turn = turn};
  if (const std::optional<AxisFacing> facing = one_sided_up_axis(model))
    return {.axis = std::string(1, "xyz"[facing->axis]), .one_sided = facing};
  if (lower_extension(model_path) == ".stl") return {.axis = "z", .stl_convention = true};
  return {};
}

}  // namespace dg::cli
