#include "tools/dockgrammar/pictures.h"

#include "geometry/errors.h"
#include "geometry/point_splats.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>

namespace dg::cli {

MeshRenderOptions picture_options(const BoundingBox& bounds, const std::string& axis) {
  MeshRenderOptions options;
  if (axis == "x") {
    options.camera.up = Vec3(1, 0, 0);
  } else if (axis == "y") {
    options.camera.up = Vec3(0, 1, 0);
  } else if (axis == "z") {
    options.camera.up = Vec3(0, 0, 1);
  } else if (axis.empty()) {
    const Vec3 size = bounds.size();
    if (size.y() < kWallThinness * std::min(size.x(), size.z())) options.camera.up = Vec3(0, 0, 1);
  } else {
    throw InputError("up axis '" + axis + "': expected x, y or z");
  }
  return options;
}

Rgba8 class_color(std::size_t i) {
  static constexpr std::array<Rgba8, 10> palette{{{228, 26, 28, 255},
                                                  {55, 126, 184, 255},
                                                  {77, 175, 74, 255},
                                                  {152, 78, 163, 255},
                                                  {255, 127, 0, 255},
                                                  {230, 200, 40, 255},
                                                  {166, 86, 40, 255},
                                                  {247, 129, 191, 255},
                                                  {100, 100, 100, 255},
                                                  {27, 158, 119, 255}}};
  return palette[i % palette.size()];
}

std::vector<Rgba8> material_colors(const TriangleMesh& mesh, const std::vector<Material>& materials) {
  std::vector<Rgba8> colors;
  if (materials.empty() || !mesh.has_materials()) return colors;
  auto channel = [](double value) { return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(value, 0.0, 1.0))); };
  for (std::uint32_t m : mesh.materials) {
    const Vec3& c = materials.at(m).diffuse;
    colors.push_back({channel(c.x()), channel(c.y()), channel(c.z()), 255});
  }
  return colors;
}

std::vector<Rgb> point_colors_of_cells(const VoxelSurface& surface, std::size_t point_count, const std::vector<Rgb>& cell_colors) {
  std::vector<Rgb> colors(point_count, Rgb{225, 225, 225});
  for (std::uint32_t c = 0; c < surface.cell_count(); ++c)
    for (std::uint32_t p : surface.points(c)) colors[p] = cell_colors[c];
  return colors;
}

void write_colored_cloud(const std::filesystem::path& png, const std::filesystem::path& ply, const PointCloud& cloud,
                         const std::vector<Rgb>& point_colors, double eps, const MeshRenderOptions& options) {
  std::vector<Rgba8> colors;
  colors.reserve(point_colors.size());
  for (const Rgb& rgb : point_colors) colors.push_back({rgb[0], rgb[1], rgb[2], 255});
  write_point_cloud(ply, cloud, &point_colors);
  write_points_picture(png, cloud.positions, colors, kSplatRadius * eps, options);
}

}  // namespace dg::cli
