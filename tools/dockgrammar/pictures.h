#pragma once
// Picture helpers shared by the subcommands that draw models.

#include "geometry/image.h"
#include "geometry/mesh.h"
#include "geometry/model_io.h"
#include "geometry/one_sided_axis.h"
#include "geometry/voxel_surface.h"
#include "geometry/render_mesh.h"
#include "symmetry/turn_axis.h"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

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
/// else the axis `model` was seen from above along (geometry/one_sided_axis.h); else empty
/// (picture_options guesses from the bounds).
struct UpAxisChoice {
  std::string axis{};
  std::optional<TurnAxis> turn{};        ///< set when the axis is the turn's
  std::optional<AxisFacing> one_sided{};  ///< set when the axis is the one the surface faces up along
};
UpAxisChoice symmetry_up_axis(const std::string& model_path, const std::string& given, const Model& model,
                              const SymmetryResult& symmetries);

/// Help text of --up for the commands that choose with symmetry_up_axis.
inline constexpr const char* kSymmetryUpAxisHelp =
    "y for glTF files; else the axis of a turn (3 or more steps to a full turn) that maps half the surface onto itself; "
    "else the axis a scan was seen from above along (surface faces up, none faces down); else z for a thin wall in the "
    "x-z plane, else y";

/// A model is guessed to be a z-up wall when its y extent is below this fraction of its smaller
/// x or z extent (walls and fences standing in the x-z plane: 0.03-0.26 for the bundled ones).
/// Thicker models are y-up, the OBJ convention: low y-up furniture and buildings (0.5-0.8) were
/// drawn on their side by a plain "thinnest along y" rule.
inline constexpr double kWallThinness = 0.35;

/// Render options with the model's up axis: `axis` "x", "y" or "z" as given to --up, or empty
/// to guess from the model's bounds: z when it is a thin wall in the x-z plane (see kWallThinness), y
/// otherwise (the common OBJ/glTF convention).
MeshRenderOptions picture_options(const BoundingBox& bounds, const std::string& axis);

/// A distinct, readable colour for class i (cycled).
Rgba8 class_color(std::size_t i);

/// One colour per triangle of `mesh`: its material's diffuse colour (8 bits per channel), or
/// none (pictures use their default colour) when the mesh or `materials` has no materials.
std::vector<Rgba8> material_colors(const TriangleMesh& mesh, const std::vector<Material>& materials);

/// The colour of each point of a cloud of `point_count` points: the colour of its cell of
/// `surface` (built from that cloud), `cell_colors` holding one per cell.
std::vector<Rgb> point_colors_of_cells(const VoxelSurface& surface, std::size_t point_count, const std::vector<Rgb>& cell_colors);

/// Writes `ply` (the cloud with `point_colors`, one per point) and `png` (its points drawn as
/// splats of kSplatRadius * eps in those colours, with `options`).
void write_colored_cloud(const std::filesystem::path& png, const std::filesystem::path& ply, const PointCloud& cloud,
                         const std::vector<Rgb>& point_colors, double eps, const MeshRenderOptions& options);

}  // namespace dg::cli
