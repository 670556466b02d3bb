#include "geometry/point_splats.h"

#include "geometry/errors.h"

#include <algorithm>
#include <array>

namespace dg {

PointSplats point_splats(const std::vector<Vec3>& points, const std::vector<Rgba8>& point_colors, double radius) {
  if (!point_colors.empty() && point_colors.size() != points.size())
    throw InputError("point picture: " + std::to_string(point_colors.size()) + " colours for " + std::to_string(points.size()) +
                     " points");
  const std::size_t stride = (points.size() + kMaxDrawnPoints - 1) / kMaxDrawnPoints;
  // Octahedron corners +-x, +-y, +-z and its eight faces, counter-clockwise from outside.
  const std::array<Vec3, 6> corners{Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY(), Vec3::UnitZ(), -Vec3::UnitZ()};
  constexpr std::array<Triangle, 8> faces{{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
  PointSplats splats;
  for (std::size_t p = 0; p < points.size(); p += std::max<std::size_t>(1, stride)) {
    const auto base = static_cast<std::uint32_t>(splats.mesh.positions.size());
    for (const Vec3& corner : corners) splats.mesh.positions.push_back(points[p] + radius * corner);
    for (const Triangle& face : faces) {
      splats.mesh.triangles.push_back({base + face[0], base + face[1], base + face[2]});
      if (!point_colors.empty()) splats.triangle_colors.push_back(point_colors[p]);
    }
  }
  return splats;
}

void write_points_picture(const std::filesystem::path& png, const std::vector<Vec3>& points,
                          const std::vector<Rgba8>& point_colors, double radius, MeshRenderOptions options) {
  const PointSplats splats = point_splats(points, point_colors, radius);
  options.draw_edges = false;
  write_mesh_picture(png, splats.mesh, splats.triangle_colors, {}, options);
}

}  // namespace dg
