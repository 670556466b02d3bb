#include "tools/dockgrammar/docking_site_picture.h"

#include "tools/dockgrammar/pictures.h"

#include "geometry/cell_pieces.h"
#include "geometry/model_io.h"
#include "geometry/render_mesh.h"

#include <algorithm>
#include <map>
#include <numeric>

namespace dg::cli {
namespace {

// (fill, curve) colours of an operation's docker and docking site.
std::pair<Rgb, Rgb> operation_colors(const DockingSite& site) {
  if (site.slippable) return {Rgb{200, 200, 200}, Rgb{110, 110, 110}};
  switch (site.operation) {
    case OperationKind::insert: return {Rgb{150, 215, 150}, Rgb{20, 120, 30}};
    case OperationKind::remove: return {Rgb{235, 160, 160}, Rgb{170, 20, 20}};
    case OperationKind::replace: break;
  }
  return {Rgb{160, 190, 235}, Rgb{20, 60, 170}};
}

}  // namespace

bool write_docking_site_picture(const std::filesystem::path& png, const std::filesystem::path& ply,
                                const PreparedModel& prepared, const DockingSiteResult& docking,
                                const std::string& up_axis) {
  if (docking.sites.empty()) return false;
  const VoxelSurface& surface = prepared.surface;

  std::vector<std::size_t> order(docking.sites.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return docking.sites[a].docker.size() > docking.sites[b].docker.size();
  });
  std::vector<Rgb> cell_color(surface.cell_count(), Rgb{225, 225, 225});
  std::vector<char> in_docker(surface.cell_count(), 0);
  for (std::size_t index : order) {
    const DockingSite& site = docking.sites[index];
    const auto [fill, curve] = operation_colors(site);
    const bool outline_only = 2 * site.docker.size() > surface.cell_count();
    for (std::uint32_t c : site.docker) {
      if (!outline_only) cell_color[c] = fill;
      in_docker[c] = 1;
    }
    for (std::uint32_t c : site.site) {
      const auto near = surface.neighbours(c);
      if (std::any_of(near.begin(), near.end(), [&](std::uint32_t n) { return in_docker[n] != 0; })) cell_color[c] = curve;
    }
    for (std::uint32_t c : site.docker) in_docker[c] = 0;
  }

  if (prepared.model.is_point_cloud()) {  // each point in its cell's colour
    const PointCloud& cloud = prepared.model.cloud;
    write_colored_cloud(png, ply, cloud, point_colors_of_cells(surface, cloud.positions.size(), cell_color), surface.eps(),
                        picture_options(cloud.bounds(), up_axis));
    return true;
  }
  // Triangles whose cells share a colour stay whole; only those across colour borders are cut.
  std::vector<Rgb> palette;
  std::map<Rgb, std::uint32_t> palette_index;
  std::vector<std::uint32_t> cell_keys(surface.cell_count());
  for (std::size_t c = 0; c < cell_keys.size(); ++c) {
    const auto [at, added] = palette_index.emplace(cell_color[c], static_cast<std::uint32_t>(palette.size()));
    if (added) palette.push_back(cell_color[c]);
    cell_keys[c] = at->second;
  }
  std::vector<std::uint32_t> triangle_keys;
  const TriangleMesh pieces = cut_where_cell_keys_differ(prepared.model.mesh, surface, cell_keys, triangle_keys);
  std::vector<Rgb> vertex_colors(pieces.positions.size());
  std::vector<Rgba8> triangle_colors(pieces.triangles.size());
  for (std::size_t t = 0; t < pieces.triangles.size(); ++t) {
    const Rgb color = palette[triangle_keys[t]];
    triangle_colors[t] = {color[0], color[1], color[2], 255};
    for (std::uint32_t v : pieces.triangles[t]) vertex_colors[v] = color;
  }
  write_mesh(ply, pieces, &vertex_colors);
  MeshRenderOptions options = picture_options(prepared.model.bounds(), up_axis);
  options.draw_edges = false;  // the cell pieces would outline every voxel
  write_mesh_picture(png, pieces, triangle_colors, {}, options);
  return true;
}

}  // namespace dg::cli
