#include "tools/dockgrammar/symmetry_report.h"

#include "geometry/cell_pieces.h"
#include "geometry/model_io.h"
#include "tools/dockgrammar/model_summary.h"
#include "tools/dockgrammar/output_folder.h"
#include "tools/dockgrammar/pictures.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace dg::cli {
namespace {

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

// Components printed with 5 significant digits (more for survey coordinates).
std::string vec(const Vec3& v, double noise) { return fitted_vector_text(v, 5, noise); }

}  // namespace

std::string describe_motion(const RigidTransform& t, const std::string& kind, double eps) {
  const double noise = 1e-6 * eps;
  if (kind == "translation") return fmt::format("t = {}, |t| = {:.6g}", vec(t.translation, noise), t.translation.norm());
  const ScrewParameters screw = screw_parameters(t);
  std::string text = fmt::format("{:.3f} deg about {} through {}", degrees(screw.angle), vec(screw.axis, 0.0),
                                 vec(screw.axis_point, noise));
  if (kind == "screw") text += fmt::format(", rise {:.6g}", screw.slide);
  return text;
}

nlohmann::json matrix_json(const RigidTransform& t) {
  const Mat4 m = t.matrix();
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < 4; ++r) rows.push_back({m(r, 0), m(r, 1), m(r, 2), m(r, 3)});
  return rows;
}

std::string symmetry_table(const SymmetryResult& result, std::size_t top, const PreparedModel& prepared) {
  const Vec3& origin = prepared.origin;
  const double eps = prepared.surface.eps();
  if (result.symmetries.empty()) return fmt::format("no symmetries found: {}\n", result.note);
  std::string out = fmt::format("{:>3}  {:<11}  {:<22}  {:<22}  {:<10}  {}\n", "#", "kind", "symmetric area",
                                "r-symmetric area", "family", "motion");
  for (std::size_t i = 0; i < std::min(top, result.symmetries.size()); ++i) {
    const DetectedSymmetry& s = result.symmetries[i];
    out += fmt::format("{:>3}  {:<11}  {:<22}  {:<22}  {:<10}  {}\n", i + 1, s.kind,
                       fmt::format("{:.4g} ({:.1f}%)", s.symmetric_area, 100.0 * s.symmetric_fraction),
                       fmt::format("{:.4g} ({:.1f}%)", s.r_symmetric_area, 100.0 * s.r_symmetric_fraction),
                       fmt::format("F{} ^{}", s.family + 1, s.power), describe_motion(shifted_motion(s.transform, origin), s.kind, eps));
  }
  out += "\nfamilies of the symmetries above (generator, repeats found):\n";
  std::vector<bool> shown(result.families.size(), false);
  for (std::size_t i = 0; i < std::min(top, result.symmetries.size()); ++i) shown[result.symmetries[i].family] = true;
  bool only_slides = false;
  for (std::size_t f = 0; f < result.families.size(); ++f) only_slides = only_slides || (shown[f] && result.families[f].count == 0);
  if (only_slides)
    out += "  (x0: the generator only slides parts along themselves, such as walls, floors and rails; no unit repeats)\n";
  for (std::size_t f = 0; f < result.families.size(); ++f) {
    if (!shown[f]) continue;
    const SymmetryFamily& family = result.families[f];
    out += fmt::format("  F{:<3} {:<11} x{:<3}{}  {}\n", f + 1, family.kind, family.count,
                       family.order > 0 ? fmt::format(" (order {})", family.order) : std::string(),
                       describe_motion(shifted_motion(family.generator, origin), family.kind, eps));
  }
  return out;
}

std::string unverified_candidates_text(const SymmetryResult& result) {
  const SymmetryStats& st = result.stats;
  if (st.unverified == 0) return "";
  return fmt::format("The {} candidates whose feature-line ends agree most often were verified; {} more were not "
                     "(`--candidates` verifies more).\n",
                     st.candidates - st.unverified, st.unverified);
}

nlohmann::json symmetry_json(const SymmetryResult& result, std::size_t top, const Vec3& origin) {
  nlohmann::json symmetries = nlohmann::json::array();
  for (std::size_t i = 0; i < std::min(top, result.symmetries.size()); ++i) {
    const DetectedSymmetry& s = result.symmetries[i];
    const SymmetryFamily& family = result.families[s.family];
    const RigidTransform motion = shifted_motion(s.transform, origin);  // in the model file's coordinates
    symmetries.push_back({{"matrix", matrix_json(motion)},
                          {"kind", s.kind},
                          {"angle_degrees", degrees(s.screw.angle)},
                          {"axis", {s.screw.axis.x(), s.screw.axis.y(), s.screw.axis.z()}},
                          {"axis_point", coordinates_json(s.screw.axis_point + origin)},
                          {"slide", s.screw.slide},
                          {"translation", coordinates_json(motion.translation)},
                          {"support", s.support},
                          {"symmetric_area", s.symmetric_area},
                          {"r_symmetric_area", s.r_symmetric_area},
                          {"symmetric_fraction", s.symmetric_fraction},
                          {"r_symmetric_fraction", s.r_symmetric_fraction},
                          {"pinned_fraction", s.pinned_fraction},
                          {"family",
                           {{"index", s.family},
                            {"generator", matrix_json(shifted_motion(family.generator, origin))},
                            {"count", family.count},
                            {"order", family.order},
                            {"power", s.power}}}});
  }
  nlohmann::json families = nlohmann::json::array();
  for (const SymmetryFamily& f : result.families)
    families.push_back({{"kind", f.kind}, {"generator", matrix_json(shifted_motion(f.generator, origin))}, {"count", f.count}, {"order", f.order},
                        {"members", f.members}, {"powers", f.powers}});
  nlohmann::json timings = nlohmann::json::object();
  for (const StageTiming& t : result.timings) timings[t.stage] = t.seconds;
  const SymmetryStats& st = result.stats;
  return {{"symmetries", symmetries},
          {"families", families},
          {"note", result.note},
          {"stats",
           {{"keypoints", st.keypoints},
            {"pair_transforms", st.pair_transforms},
            {"candidates", st.candidates},
            {"verified", st.verified},
            {"unverified", st.unverified},
            {"rejected_early", st.rejected_early},
            {"rejected_small", st.rejected_small},
            {"seconds_per_verified", st.seconds_per_verified}}},
          {"timings_s", timings}};
}

void write_symmetry_pictures(const std::filesystem::path& folder, const PreparedModel& prepared,
                             const SymmetryResult& result, std::size_t top, const std::string& up_axis) {
  create_output_folder(folder);
  const VoxelSurface& surface = prepared.surface;
  const CellMatcher matcher(surface, nullptr, result.region);
  enum : std::uint8_t { grey = 0, pink = 1, red = 2, blue = 4 };
  auto color_of = [](std::uint32_t state) {
    if (state & blue) return (state & red) ? Rgb{150, 60, 200} : Rgb{40, 90, 220};
    if (state & red) return Rgb{220, 40, 40};
    if (state & pink) return Rgb{240, 160, 160};
    return Rgb{170, 170, 170};
  };
  for (std::size_t i = 0; i < std::min(top, result.symmetries.size()); ++i) {
    const DetectedSymmetry& s = result.symmetries[i];
    std::vector<std::uint32_t> state(surface.cell_count(), grey);
    for (std::uint32_t c : s.region.symmetric_cells) state[c] = pink;
    for (std::uint32_t c : s.region.r_symmetric_cells) state[c] = red;
    std::vector<char> image;
    matcher.image_of_cells(s.region.r_symmetric_cells, s.transform, image);
    for (std::uint32_t c = 0; c < surface.cell_count(); ++c)
      if (image[c]) state[c] |= blue;
    const std::filesystem::path ply = folder / fmt::format("symmetry_{:02}.ply", i + 1),
                                png = folder / fmt::format("symmetry_{:02}.png", i + 1);
    MeshRenderOptions options = picture_options(prepared.model.bounds(), up_axis);
    if (prepared.model.is_point_cloud()) {  // each point in its cell's colour
      std::vector<Rgb> cell_colors;
      for (std::uint32_t st : state) cell_colors.push_back(color_of(st));
      const PointCloud& cloud = prepared.model.cloud;
      write_colored_cloud(png, ply, cloud, point_colors_of_cells(surface, cloud.positions.size(), cell_colors), surface.eps(),
                          options);
      continue;
    }
    // Triangles whose cells share a state stay whole; only those across state borders are cut.
    std::vector<std::uint32_t> piece_states;
    const TriangleMesh pieces = cut_where_cell_keys_differ(prepared.model.mesh, surface, state, piece_states);
    std::vector<Rgb> colors(pieces.positions.size());
    std::vector<Rgba8> triangle_colors(pieces.triangles.size());
    for (std::size_t t = 0; t < pieces.triangles.size(); ++t) {
      const Rgb color = color_of(piece_states[t]);
      for (std::uint32_t v : pieces.triangles[t]) colors[v] = color;
      triangle_colors[t] = {color[0], color[1], color[2], 255};
    }
    write_mesh(ply, pieces, &colors);
    options.draw_edges = false;  // the cell pieces would outline every voxel
    write_mesh_picture(png, pieces, triangle_colors, {}, options);
  }
}

}  // namespace dg::cli
