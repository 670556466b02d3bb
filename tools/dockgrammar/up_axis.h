#pragma once
// A model's up axis: from --up, its file's convention, its dominant turn or the way its surface
// faces. Pictures stand the model on it; analyze stores it for generate and resize.

#include "geometry/model_io.h"
#include "geometry/one_sided_axis.h"
#include "symmetry/symmetry_detection.h"
#include "symmetry/turn_axis.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace dg::cli {

/// Registers `--up x|y|z` (the model's up axis in pictures) on a command. `axis` stays empty
/// when the option is absent; a value other than x, y or z is a usage error (exit status 2).
/// `fallback` says in the help text what an absent option means.
void add_up_option(CLI::App& command, std::string& axis, const std::string& fallback);

/// The up axis to use for a model file: `given` (from --up) when set; else "y" for glTF files
/// (.gltf/.glb: glTF 2.0 defines +Y as up); else empty (guess from the shape, see picture_options).
std::string model_up_axis(const std::string& model_path, const std::string& given);

/// The up axis a command that found the model's symmetries draws with (and analyze stores for
/// generate and resize), and the turn it was read from: model_up_axis's when that is set; else
/// the coordinate axis of the model's dominant turn (symmetry/turn_axis.h), as "x", "y" or "z";
/// else the axis `model` was seen from above along (geometry/one_sided_axis.h); else z for STL
/// files (z-up by convention: CAD, 3D printing, Blender's STL export); else empty
/// (picture_options guesses from the bounds).
struct UpAxisChoice {
  std::string axis{};
  std::optional<TurnAxis> turn{};        ///< set when the axis is the turn's
  std::optional<AxisFacing> one_sided{};  ///< set when the axis is the one the surface faces up along
  bool stl_convention = false;           ///< set when the axis is z because the file is STL
};
UpAxisChoice symmetry_up_axis(const std::string& model_path, const std::string& given, const Model& model,
                              const SymmetryResult& symmetries);

/// Help text of --up for the commands that choose with symmetry_up_axis.
inline constexpr const char* kSymmetryUpAxisHelp =
    "y for glTF files; else the axis of a turn (3 or more steps to a full turn) that maps half the surface onto itself; "
    "else the axis a scan was seen from above along (surface faces up, none faces down); else z for STL files; else z "
    "for a thin wall in the x-z plane, else y";

}  // namespace dg::cli
