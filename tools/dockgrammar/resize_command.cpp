// `dockgrammar resize GRAMMAR --grid NAME=N[xM...] [--grid ...] -o OUT`: a resized copy of the
// exemplar (grids not named keep the exemplar's counts).

#include "tools/dockgrammar/commands.h"

#include "geometry/errors.h"
#include "geometry/model_io.h"
#include "geometry/point_splats.h"
#include "geometry/submesh.h"
#include "grammar/grammar_file.h"
#include "synthesis/several_grids.h"
#include "tools/dockgrammar/output_folder.h"
#include "tools/dockgrammar/output_frame.h"
#include "tools/dockgrammar/number_checks.h"
#include "tools/dockgrammar/pictures.h"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <limits>
#include <memory>

namespace dg::cli {
namespace {

// "facade=5x7" -> {"facade", {5, 7}}.
std::pair<std::string, std::vector<int>> parse_grid_counts(const std::string& text) {
  const std::size_t equals = text.find('=');
  if (equals == std::string::npos || equals == 0 || equals + 1 == text.size())
    throw InputError("--grid " + text + ": expected NAME=N, NAME=NxM or NAME=NxMxK");
  std::vector<int> counts;
  std::size_t start = equals + 1;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('x', start), text.size());
    int value = 0;
    const auto [ptr, ec] = std::from_chars(text.data() + start, text.data() + end, value);
    if (ec != std::errc() || ptr != text.data() + end) throw InputError("--grid " + text + ": counts must be whole numbers");
    counts.push_back(value);
    start = end + 1;
  }
  return {text.substr(0, equals), counts};
}

// Throws LimitError when the resizes would place more than `limit` triangles (points).
void check_resized_size(const ShapeGrammar& grammar, const std::vector<GridResize>& resizes, std::size_t limit) {
  const std::size_t size = resized_model_size(grammar, resizes);
  if (size <= limit) return;
  std::string named;
  for (const GridResize& resize : resizes)
    named += fmt::format("{}{}={}", named.empty() ? "" : ", ", grammar.grids[resize.grid].rule.name, fmt::join(resize.counts, "x"));
  const double bytes = 200.0 * static_cast<double>(size);
  throw LimitError(fmt::format("{} would place about {} {} (about {} while building), more than --max-triangles {}; "
                               "raise it to build it anyway",
                               named, size, is_point_grammar(grammar) ? "points" : "triangles",
                               bytes >= 1e9 ? fmt::format("{:.0f} GB", bytes / 1e9) : fmt::format("{:.0f} MB", bytes / 1e6), limit));
}

}  // namespace

void add_resize_command(CLI::App& app) {
  struct Options {
    std::string grammar;
    std::vector<std::string> grids;
    std::string output;
    bool picture = false;
    bool quiet = false;
    std::string up;
    std::size_t max_size = 50'000'000;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand("resize", "Resize grid rules of a grammar (from analyze) and write the model");
  command->add_option("GRAMMAR", options->grammar, "Grammar file written by analyze (NAME.grammar.json)")->required();
  command->add_option("--grid", options->grids, "Grid counts as NAME=N, NAME=NxM or NAME=NxMxK (one per direction); repeat for several grids; grids not named keep the exemplar's counts")->required();
  command->add_option("-o,--output", options->output, "Output mesh: .obj, .ply or .glb (.ply for a grammar made from a point cloud)")->required();
  command->add_flag("--picture", options->picture, "Also write a PNG picture of the result next to it (OUT with .png)");
  command->add_flag("-q,--quiet", options->quiet, "No message on stderr (errors still go there)");
  add_up_option(*command, options->up, "the axis analyze --up stored in the grammar file, else guessed from the exemplar");
  command
      ->add_option("--max-triangles", options->max_size,
                   "Refuse a resize that would place more triangles (points, for a point-cloud grammar) than this; "
                   "each costs about 200 bytes while it is built")
      ->capture_default_str()
      ->check(number_in(std::size_t{1}, std::numeric_limits<std::size_t>::max()));
  command->callback([options] {
    const ShapeGrammar grammar = read_grammar(options->grammar);
    std::vector<GridResize> resizes;
    for (const std::string& text : options->grids) {
      auto [name, counts] = parse_grid_counts(text);
      const auto grid =
          std::find_if(grammar.grids.begin(), grammar.grids.end(), [&](const GridWithPieces& g) { return g.rule.name == name; });
      if (grid == grammar.grids.end()) {
        std::string names;
        for (const GridWithPieces& g : grammar.grids) names += (names.empty() ? "" : ", ") + g.rule.name;
        throw InputError(fmt::format("{}: no grid named '{}' (grids: {})", options->grammar, name, names.empty() ? "none" : names));
      }
      resizes.push_back({static_cast<std::size_t>(grid - grammar.grids.begin()), std::move(counts)});
    }
    check_resized_size(grammar, resizes, options->max_size);
    const std::filesystem::path output(options->output);
    const MeshRenderOptions picture = picture_options(exemplar_bounds(grammar), options->up.empty() ? grammar.up_axis : options->up);
    if (is_point_grammar(grammar)) {
      const PointCloud result = resize_grids_points(grammar, resizes);
      create_output_folder(output.parent_path());
      write_point_cloud(output, transformed(result, to_source_frame(grammar)));  // rejects outputs other than .ply
      if (options->picture)
        write_points_picture(std::filesystem::path(output).replace_extension(".png"), result.positions, {},
                             kSplatRadius * grammar.eps, picture);
      if (!options->quiet) fmt::print(stderr, "wrote {} ({} points)\n", options->output, result.positions.size());
      return;
    }
    const TriangleMesh result = resize_grids(grammar, resizes);
    create_output_folder(output.parent_path());
    const RigidTransform to_file = file_frame(output, picture.camera.up.normalized()).after(to_source_frame(grammar));
    write_mesh_with_materials(output, transformed(result, to_file), grammar.materials);
    if (options->picture)
      write_mesh_picture(std::filesystem::path(output).replace_extension(".png"), result, material_colors(result, grammar.materials),
                         {}, picture);
    if (!options->quiet) fmt::print(stderr, "wrote {} ({} triangles)\n", options->output, result.triangles.size());
  });
}

}  // namespace dg::cli
