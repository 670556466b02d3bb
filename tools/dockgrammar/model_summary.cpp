#include "tools/dockgrammar/model_summary.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace dg::cli {
namespace {

std::string format_vector(const Vec3& v) { return coordinates_text(v, 6); }

/// "none", or the count and the names (the first eight, then how many more).
std::string materials_text(const std::vector<Material>& materials) {
  if (materials.empty()) return "none";
  std::string names;
  for (std::size_t i = 0; i < materials.size() && i < 8; ++i) names += (i == 0 ? "" : ", ") + materials[i].name;
  if (materials.size() > 8) names += fmt::format(", and {} more", materials.size() - 8);
  return fmt::format("{} ({})", materials.size(), names);
}

}  // namespace

std::vector<std::vector<std::string>> material_groups(const PreparedModel& prepared) {
  std::vector<std::vector<std::string>> groups;
  const std::vector<std::uint32_t>& classes = prepared.material_classes;
  for (std::uint32_t m = 0; m < classes.size(); ++m) {
    if (classes[m] != m) continue;  // the first material of each class opens it
    std::vector<std::string> names;
    for (std::uint32_t other = m; other < classes.size(); ++other)
      if (classes[other] == m) names.push_back(prepared.model.materials[other].name);
    if (names.size() > 1) groups.push_back(std::move(names));
  }
  return groups;
}

std::string coordinates_text(const Vec3& v, int digits) {
  auto text = [&](double x) {
    const int whole_digits = x == 0.0 ? 1 : static_cast<int>(std::floor(std::log10(std::abs(x)))) + 1;
    return fmt::format("{:.{}g}", x, std::max(digits, whole_digits + 3));
  };
  return fmt::format("({}, {}, {})", text(v.x()), text(v.y()), text(v.z()));
}

std::string fitted_vector_text(const Vec3& v, int digits, double noise) {
  const double zero = std::max(noise, 1e-6 * v.norm());
  auto clean = [&](double x) { return std::abs(x) <= zero ? 0.0 : x; };
  return coordinates_text(Vec3(clean(v.x()), clean(v.y()), clean(v.z())), digits);
}

nlohmann::json coordinates_json(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

std::string origin_text(const PreparedModel& prepared) {
  if (prepared.origin.isZero()) return "";
  return fmt::format("The model lies too far from its file's origin for the voxel grid: it was analysed moved by -{}; "
                     "motions and cut planes are given in the file's coordinates, the grammar file keeps that origin, and "
                     "resize and generate move what they build back.",
                     coordinates_text(prepared.origin, 6));
}

std::string summary_text(const PreparedModel& prepared) {
  const CleaningReport& c = prepared.cleaning;
  const VoxelSurfaceStats stats = prepared.surface.stats();
  std::string out;
  auto line = [&](std::string_view key, const std::string& value) { out += fmt::format("{:<15}{}\n", key, value); };
  line("model", prepared.model.source_path);
  if (c.point_cloud) {
    line("points", fmt::format("{} ({} read, {} duplicates and {} invalid normals dropped)", c.vertices, c.input_vertices,
                               c.duplicate_points_dropped, c.invalid_normals_dropped));
  } else {
    line("vertices", fmt::format("{} ({} read, {} after welding equal positions)", c.vertices, c.input_vertices,
                                 c.welded_vertices));
    line("triangles", fmt::format("{} ({} read, {} degenerate dropped, {} duplicated)", c.triangles, c.input_triangles,
                                  c.degenerate_dropped, c.duplicate_triangles));
    line("edges", fmt::format("{} boundary, {} non-manifold, {} inconsistently oriented; {} split at T-junctions for analysis",
                              c.boundary_edges, c.non_manifold_edges, c.inconsistent_edges, c.t_junctions_split));
    line("components", fmt::format("{}{}", c.components, c.closed_and_oriented ? " (closed, consistently oriented)" : ""));
    line("materials", materials_text(prepared.model.materials));
    if (prepared.materials_matched()) {
      std::string matching = "symmetries map each material onto itself";
      for (const std::vector<std::string>& group : material_groups(prepared))
        matching += fmt::format("; {} count as one", fmt::join(group, ", "));
      line("matching", matching);
    }
  }
  line("bounds", fmt::format("{} .. {}, size {}", format_vector(c.bounds.min), format_vector(c.bounds.max),
                             format_vector(c.bounds.size())));
  line("r, eps", fmt::format("{:.6g}, {:.6g} (model units)", prepared.surface.r(), prepared.surface.eps()));
  if (!prepared.origin.isZero()) line("origin", fmt::format("{} (the model was moved by minus this for the voxel grid)",
                                                            coordinates_text(prepared.origin, 6)));
  line("voxel surface", fmt::format("{} voxels, {} planes, {} lines, {} points, {:.1f} MB", stats.voxels, stats.planes,
                                    stats.lines, stats.points, static_cast<double>(stats.memory_bytes) / 1e6));
  if (c.point_cloud) {
    const double eps = prepared.surface.eps();
    line("sampling", fmt::format("points {:.3g} apart, {:.3f} eps off the surface (rms) within {} eps, {:.3f} within {} eps",
                                 prepared.cloud_sampling.spacing, prepared.cloud_sampling.noise / eps, kCloudStatisticsRadius,
                                 prepared.cloud_sampling.noise_wide / eps, 2.0 * kCloudStatisticsRadius));
  } else {
    line("feature lines", fmt::format("{} lines, total length {:.6g}, {} samples", prepared.feature_lines.lines.size(),
                                      prepared.feature_lines.total_length(), prepared.feature_lines.samples.size()));
  }
  std::string timings;
  for (const StageTiming& t : prepared.timings) timings += fmt::format("{}{} {:.3f} s", timings.empty() ? "" : ", ", t.stage, t.seconds);
  line("timings", timings);
  return out;
}

nlohmann::json material_names(const std::vector<Material>& materials) {
  nlohmann::json names = nlohmann::json::array();
  for (const Material& material : materials) names.push_back(material.name);
  return names;
}

nlohmann::json summary_json(const PreparedModel& prepared) {
  const VoxelSurfaceStats stats = prepared.surface.stats();
  nlohmann::json timings = nlohmann::json::object();
  for (const StageTiming& t : prepared.timings) timings[t.stage] = t.seconds;
  return {{"model", prepared.model.source_path},
          {"cleaning", to_json(prepared.cleaning)},
          {"materials", material_names(prepared.model.materials)},
          {"match_materials", prepared.materials_matched()},
          {"material_groups", material_groups(prepared)},
          {"origin", coordinates_json(prepared.origin)},
          {"r", prepared.surface.r()},
          {"eps", prepared.surface.eps()},
          {"voxel_surface",
           {{"voxels", stats.voxels},
            {"cells", stats.voxels},
            {"planes", stats.planes},
            {"lines", stats.lines},
            {"points", stats.points},
            {"memory_bytes", stats.memory_bytes}}},
          {"feature_lines",
           {{"count", prepared.feature_lines.lines.size()},
            {"total_length", prepared.feature_lines.total_length()},
            {"samples", prepared.feature_lines.samples.size()}}},
          {"cloud_sampling", prepared.cleaning.point_cloud ? nlohmann::json{{"spacing", prepared.cloud_sampling.spacing},
                                                                  {"noise", prepared.cloud_sampling.noise},
                                                                  {"noise_wide", prepared.cloud_sampling.noise_wide}}
                                                : nlohmann::json(nullptr)},
          {"timings_s", timings}};
}

}  // namespace dg::cli
