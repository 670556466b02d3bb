#pragma once
// Picture helpers shared by the subcommands that draw models.

#include "geometry/image.h"
#include "geometry/mesh.h"
#include "geometry/model_io.h"
#include "geometry/voxel_surface.h"
#include "geometry/render_mesh.h"
#include "tools/dockgrammar/up_axis.h"

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace dg::cli {

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
