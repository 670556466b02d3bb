#include "tools/dockgrammar/grammar_report.h"

#include "geometry/atomic_file.h"
#include "geometry/model_io.h"
#include "tools/dockgrammar/pictures.h"
#include "tools/dockgrammar/symmetry_report.h"

#include <fmt/format.h>

#include <cmath>

namespace dg::cli {
namespace {

constexpr const char* kMissing =
    "context-free rules (docking sites, dockers, insert/delete/replace operations, non-terminals and productions) are "
    "not implemented yet; the grammar holds grid rules only";

std::string counts_text(const GridRule& grid) {
  std::string text;
  for (const GridDirection& d : grid.directions) text += fmt::format("{}{}", text.empty() ? "" : "x", d.count);
  return text;
}

// Components with 6 significant digits; rounding noise (below 1e-9 of the length) and -0 show as 0.
std::string vec(const Vec3& v) {
  const double noise = 1e-9 * v.norm();
  auto clean = [&](double x) { return std::abs(x) <= noise ? 0.0 : x; };
  return fmt::format("({:.6g}, {:.6g}, {:.6g})", clean(v.x()), clean(v.y()), clean(v.z()));
}

nlohmann::json timings_json(const AnalysisReport& report) {
  nlohmann::json timings = nlohmann::json::object();
  for (const StageTiming& t : report.prepared.timings) timings[t.stage] = t.seconds;
  for (const StageTiming& t : report.symmetries.timings) timings["symmetry " + t.stage] = t.seconds;
  timings["grid rules"] = report.grid_seconds;
  return timings;
}

}  // namespace

std::string analysis_text(const AnalysisReport& report) {
  std::string out = fmt::format("model {}: r = {:.6g}, eps = {:.6g}\n", report.prepared.model.source_path,
                                report.prepared.surface.r(), report.prepared.surface.eps());
  out += fmt::format("symmetries: {} in {} families\n", report.symmetries.symmetries.size(), report.symmetries.families.size());
  if (report.grammar.grids.empty()) out += "grids: none found\n";
  for (const GridWithPieces& grid : report.grammar.grids) {
    out += fmt::format("grid {}: {}-grid, counts {} (resize with --grid {}={})\n", grid.rule.name, grid.rule.directions.size(),
                       counts_text(grid.rule), grid.rule.name, counts_text(grid.rule));
    for (const GridDirection& d : grid.rule.directions)
      out += fmt::format("  direction t = {}, pitch {:.6g}, {} units, first cut at {:.6g}\n", vec(d.translation), d.pitch,
                         d.count, d.cut);
  }
  out += fmt::format("grammar written to {}\nnote: {}\n", report.grammar_path.string(), kMissing);
  return out;
}

nlohmann::json analysis_json(const AnalysisReport& report) {
  nlohmann::json grids = nlohmann::json::array();
  for (const GridWithPieces& grid : report.grammar.grids) {
    nlohmann::json counts = nlohmann::json::array(), transforms = nlohmann::json::array(), pieces = nlohmann::json::array();
    for (const GridDirection& d : grid.rule.directions) {
      counts.push_back(d.count);
      RigidTransform t;
      t.translation = d.translation;
      const Mat4 m = t.matrix();
      nlohmann::json rows = nlohmann::json::array();
      for (int r = 0; r < 4; ++r) rows.push_back({m(r, 0), m(r, 1), m(r, 2), m(r, 3)});
      transforms.push_back(rows);
    }
    for (const GridPiece& p : grid.pieces) pieces.push_back({{"name", piece_name(p.classes)}, {"triangles", p.mesh.triangles.size()}});
    grids.push_back({{"name", grid.rule.name},
                     {"dims", grid.rule.directions.size()},
                     {"counts", counts},
                     {"transforms", transforms},
                     {"count_range", {grid.rule.min_count, grid.rule.max_count}},
                     {"pieces", pieces}});
  }
  return {{"model", report.prepared.model.source_path},
          {"r", report.prepared.surface.r()},
          {"eps", report.prepared.surface.eps()},
          {"symmetries", report.symmetries.symmetries.size()},
          {"families", report.symmetries.families.size()},
          {"docking_sites", nullptr},
          {"dockers", nullptr},
          {"operations", {{"insert", nullptr}, {"delete", nullptr}, {"replace", nullptr}}},
          {"nonterminals", nullptr},
          {"productions", nullptr},
          {"grids", grids},
          {"grammar_file", report.grammar_path.string()},
          {"timings_s", timings_json(report)},
          {"missing", kMissing}};
}

void write_analysis_report(const std::filesystem::path& path, const AnalysisReport& report) {
  const PreparedModel& prepared = report.prepared;
  const CleaningReport& c = prepared.cleaning;
  std::string md = fmt::format("# Analysis of {}\n\n", prepared.model.source_path);
  md += fmt::format("r = {:.6g}, eps = {:.6g} (model units). {} vertices, {} triangles ({} degenerate dropped, {} duplicated), "
                    "{} boundary and {} non-manifold edges, {} components.\n\n",
                    prepared.surface.r(), prepared.surface.eps(), c.vertices, c.triangles, c.degenerate_dropped,
                    c.duplicate_triangles, c.boundary_edges, c.non_manifold_edges, c.components);
  md += "## Symmetries\n\nOrdered by r-symmetric area; families group a motion with its powers.\n\n```\n";
  md += symmetry_table(report.symmetries, 20);
  md += "```\n\n## Grid rules\n\n";
  if (report.grammar.grids.empty()) md += "No grid found (no translational repetition with at least two units whose cut planes cross only r-symmetric area).\n\n";
  for (const GridWithPieces& grid : report.grammar.grids) {
    md += fmt::format("### {} ({}-grid, counts {})\n\n| direction | translation | pitch | units | first cut |\n|---|---|---|---|---|\n",
                      grid.rule.name, grid.rule.directions.size(), counts_text(grid.rule));
    for (std::size_t i = 0; i < grid.rule.directions.size(); ++i) {
      const GridDirection& d = grid.rule.directions[i];
      md += fmt::format("| {} | {} | {:.6g} | {} | {:.6g} |\n", i + 1, vec(d.translation), d.pitch, d.count, d.cut);
    }
    md += "\nPieces (class per direction: 1 = head, placed once; 2 = repeated unit; 3 = tail, placed after the last unit):\n\n";
    for (const GridPiece& p : grid.pieces) md += fmt::format("- {}: {} triangles\n", piece_name(p.classes), p.mesh.triangles.size());
    md += fmt::format("\nAllowed counts per direction: {}..{}. Picture: `{}.png`.\n\n", grid.rule.min_count, grid.rule.max_count,
                      path.stem().stem().string() + "." + grid.rule.name);
  }
  md += fmt::format("## Not yet built\n\n{}.\n\n## Timings (seconds)\n\n", kMissing);
  const nlohmann::json timings = timings_json(report);
  for (const auto& [stage, seconds] : timings.items()) md += fmt::format("- {}: {:.3f}\n", stage, seconds.get<double>());
  write_file_atomically(path, [&](std::ostream& out) { out << md; }, false);
}

void write_analysis_pictures(const std::filesystem::path& folder, const std::string& stem, const AnalysisReport& report) {
  const TriangleMesh& mesh = report.prepared.model.mesh;
  for (const GridWithPieces& grid : report.grammar.grids) {
    const GridCut grid_cut = cut_along_grid(mesh, grid.rule, report.grammar.eps);
    const TriangleMesh& cut = grid_cut.mesh;
    std::vector<Rgba8> colors(cut.triangles.size());
    std::vector<Rgb> vertex_colors(cut.positions.size());
    for (std::size_t t = 0; t < cut.triangles.size(); ++t) {
      // Class per direction as stored in the grammar; later units (copies) shade like the unit,
      // alternately darker so the repeats can be counted.
      std::size_t class_index = 0, parity = 0;
      for (std::size_t i = 0; i < grid.rule.directions.size(); ++i) {
        const std::size_t slab = grid_cut.slabs[t][i];
        const int cls = slab_class(slab, grid.rule.directions[i].count);
        class_index = 3 * class_index + static_cast<std::size_t>(cls < 0 ? 1 : cls);
        if (cls != 0 && cls != 2) parity += slab;
      }
      Rgba8 color = class_color(class_index);
      if (parity % 2 == 1) color = {static_cast<std::uint8_t>(color.r * 3 / 4), static_cast<std::uint8_t>(color.g * 3 / 4),
                                    static_cast<std::uint8_t>(color.b * 3 / 4), 255};
      colors[t] = color;
      for (std::uint32_t v : cut.triangles[t]) vertex_colors[v] = {color.r, color.g, color.b};
    }
    write_mesh(folder / (stem + "." + grid.rule.name + ".ply"), cut, &vertex_colors);
    write_mesh_picture(folder / (stem + "." + grid.rule.name + ".png"), cut, colors, {}, picture_options(mesh));
  }
}

}  // namespace dg::cli
