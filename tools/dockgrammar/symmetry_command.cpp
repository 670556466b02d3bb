// `dockgrammar symmetry MODEL`: partial rigid symmetries ordered by r-symmetric area.

#include "tools/dockgrammar/commands.h"
#include "tools/dockgrammar/model_options.h"
#include "tools/dockgrammar/model_summary.h"
#include "tools/dockgrammar/number_checks.h"
#include "tools/dockgrammar/pictures.h"
#include "tools/dockgrammar/symmetry_report.h"

#include <fmt/core.h>

#include <memory>

namespace dg::cli {

void add_symmetry_command(CLI::App& app) {
  struct Options {
    ModelOptions model;
    SearchOptions search;
    std::size_t top = 10;
    std::string output;
    std::string up;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand("symmetry", "Find partial rigid symmetries (translations, rotations, screw motions)");
  add_model_options(*command, options->model);
  add_search_options(*command, options->search);
  command->add_option("--top", options->top, "How many symmetries to list and draw")
      ->capture_default_str()
      ->check(number_in(std::size_t{1}, std::size_t{100000}));
  command->add_option("-o,--output", options->output, "Folder for coloured PLY and PNG pictures of the top symmetries");
  add_up_option(*command, options->up, kSymmetryUpAxisHelp);
  command->callback([options] {
    const auto threads = limit_threads(options->model.threads);
    const ProgressCallback progress = stderr_progress(options->model.quiet);
    const PreparedModel prepared = prepare_model(options->model.model_path, options->model.prepare, progress);
    const SymmetryResult result = detect_symmetries(prepared, symmetry_options(options->search), progress);
    if (!options->output.empty())
      write_symmetry_pictures(options->output, prepared, result, options->top,
                              symmetry_up_axis(options->model.model_path, options->up, prepared.model, result).axis);
    if (options->model.json) {
      nlohmann::json out = symmetry_json(result, options->top, prepared.origin);
      out["model"] = prepared.model.source_path;
      out["r"] = prepared.surface.r();
      out["eps"] = prepared.surface.eps();
      out["origin"] = coordinates_json(prepared.origin);
      out["tolerance"] = cell_tolerances(result.region, prepared.model.is_point_cloud()).offset_eps;
      for (const StageTiming& t : prepared.timings) out["timings_s"][t.stage] = t.seconds;
      fmt::print("{}\n", out.dump(2));
    } else {
      const std::string moved = origin_text(prepared);
      fmt::print("model {}: r = {:.6g}, eps = {:.6g}\n{}\n{}", prepared.model.source_path, prepared.surface.r(),
                 prepared.surface.eps(), moved.empty() ? "" : "origin: " + moved + "\n",
                 symmetry_table(result, options->top, prepared));
      if (const std::string unverified = unverified_candidates_text(result); !unverified.empty()) fmt::print("\n{}", unverified);
    }
  });
}

}  // namespace dg::cli
