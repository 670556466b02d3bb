// `dockgrammar analyze MODEL`: symmetries, grid rules, docking sites, context-free rules, the grammar
// file, a report and pictures.

#include "tools/dockgrammar/commands.h"
#include "tools/dockgrammar/grammar_report.h"
#include "tools/dockgrammar/model_options.h"
#include "tools/dockgrammar/output_folder.h"
#include "tools/dockgrammar/pictures.h"
#include "tools/dockgrammar/number_checks.h"

#include "geometry/stopwatch.h"
#include "grammar/context_free.h"
#include "grammar/docking_sites.h"
#include "grammar/grammar_file.h"
#include "grammar/grid_cut.h"
#include "grammar/grid_rules.h"
#include "grammar/grid_seams.h"
#include "grammar/material_analysis.h"
#include "grammar/tolerance_hint.h"
#include "symmetry/symmetry_detection.h"

#include <fmt/core.h>

#include <filesystem>
#include <memory>

namespace dg::cli {

void add_analyze_command(CLI::App& app) {
  struct Options {
    ModelOptions model;
    SearchOptions search;
    std::size_t site_symmetries = DockingSiteOptions{}.max_symmetries;
    std::string output = ".";
    std::uint64_t seed = 1;
    std::string up;
    bool geometry_only = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "analyze", "Find the symmetries, grid rules, docking sites and context-free rules of a model; write "
      "NAME.grammar.json, NAME.report.md and pictures (what each stage finds: docs/analyze.md)");
  add_model_options(*command, options->model);
  add_search_options(*command, options->search);
  command
      ->add_option("--site-symmetries", options->site_symmetries,
                   "Symmetries whose motions give docking sites, one per repetition family, largest r-symmetric area "
                   "first; more lets motions of small parts (one branch level onto the next) give context-free rules")
      ->check(number_in(std::size_t(1), std::size_t(10000)))
      ->capture_default_str();
  command->add_option("-o,--output", options->output, "Output folder (created if needed)")->capture_default_str();
  command->add_option("--seed", options->seed, "Seed of the random independent sets that resolve conflicting docking sites")
      ->capture_default_str()->check(seed_number());
  command->add_flag("--geometry-only", options->geometry_only,
                    "When geometry alone gives no grid but matching materials (some grouped as one) would, keep to "
                    "geometry and only name the options in a hint (default: go on with the materials matched)");
  add_up_option(*command, options->up, std::string(kSymmetryUpAxisHelp) + "; stored in the grammar file for generate");
  command->callback([options] {
    const auto threads = limit_threads(options->model.threads);
    const ProgressCallback progress = stderr_progress(options->model.quiet);
    PreparedModel prepared = prepare_model(options->model.model_path, options->model.prepare, progress);
    SymmetryResult symmetries = detect_symmetries(prepared, symmetry_options(options->search), progress);

    Stopwatch stopwatch;
    std::vector<StageTiming> grammar_timings;
    ShapeGrammar grammar;
    // The grammar's grids: the rules with their pieces cut from the prepared model.
    auto add_grids = [&](std::vector<GridRule> rules) {
      for (GridRule& rule : rules) {
        std::vector<GridPiece> pieces = prepared.model.is_point_cloud()
                                            ? cut_grid_points(prepared.model.cloud, rule)
                                            : cut_grid_pieces(prepared.model.mesh, rule, prepared.surface.eps());
        rule.seam_misfit = grid_seam_misfit(rule, pieces, prepared.surface.eps());
        grammar.grids.push_back({std::move(rule), std::move(pieces)});
      }
    };
    add_grids(find_grids(prepared, symmetries, {}, progress));
    std::optional<ToleranceHint> hint = tolerance_hint(prepared, symmetries, grammar.grids);
    grammar_timings.push_back({"grid rules", stopwatch.lap()});
    // Geometry alone gave no grid: materials matched, with the ones that take one another's
    // place grouped, may give one; analyze then goes on with them (with --geometry-only it only
    // names them).
    std::optional<MaterialHint> materials;
    if (material_hint_applies(prepared, options->model.prepare, grammar.grids.size())) {  // timed only when it runs
      const SymmetryOptions search = symmetry_options(options->search);
      std::optional<GroupedMaterialAnalysis> grouped;
      if (options->geometry_only) {
        materials = material_hint(prepared, options->model.prepare, search, grammar.grids.size(), progress);
      } else if ((grouped = analyze_with_materials_grouped(options->model.model_path, prepared, options->model.prepare, search,
                                                           grammar.grids.size(), progress))) {
        // The stages so far become one line: the grouped model reports its own.
        stopwatch.lap();
        grammar_timings = {{"analysis by geometry alone (no grid)",
                            total_seconds(prepared.timings) + total_seconds(symmetries.timings) + total_seconds(grammar_timings)},
                           {"material hint", grouped->grouping_seconds}};
        prepared = std::move(grouped->prepared);
        symmetries = std::move(grouped->symmetries);
        materials = std::move(grouped->hint);
        add_grids(std::move(grouped->grids));
        hint = tolerance_hint(prepared, symmetries, grammar.grids);
        grammar_timings.push_back({"grid rules", grouped->grid_seconds + stopwatch.lap()});
      }
      if (!grouped) grammar_timings.push_back({"material hint", stopwatch.lap()});
    }
    grammar.source_name = std::filesystem::path(options->model.model_path).filename().string();
    grammar.source_hash = file_hash(options->model.model_path);
    grammar.r = prepared.surface.r();
    grammar.eps = prepared.surface.eps();
    grammar.origin = prepared.origin;
    const UpAxisChoice up = symmetry_up_axis(options->model.model_path, options->up, prepared.model, symmetries);
    grammar.up_axis = up.axis;
    grammar.exemplar = prepared.model.mesh;
    if (prepared.model.is_point_cloud()) grammar.exemplar_points = prepared.model.cloud;
    grammar.materials = prepared.model.materials;
    DockingSiteOptions site_options;
    site_options.max_symmetries = options->site_symmetries;
    const DockingSiteResult docking = find_docking_sites(prepared, symmetries, site_options, progress);
    grammar_timings.push_back({"docking sites", stopwatch.lap()});
    ContextFreeOptions cf_options;
    cf_options.seed = options->seed;
    ContextFreeStats cf_stats;
    grammar.context_free = build_context_free_grammar(prepared, docking, cf_options, &cf_stats, progress);
    grammar_timings.push_back({"context-free rules", stopwatch.lap()});

    const std::filesystem::path folder(options->output);
    create_output_folder(folder);
    std::string stem = std::filesystem::path(options->model.model_path).stem().string();
    const std::filesystem::path grammar_path = folder / (stem + ".grammar.json");
    write_grammar(grammar_path, grammar);
    AnalysisReport report{prepared, symmetries, grammar, docking, cf_stats, grammar_timings, grammar_path,
                          folder / (stem + ".report.md"), {}, hint, materials, up};
    write_analysis_report(report);
    report.pictures = write_analysis_pictures(folder, stem, report);
    if (options->model.json)
      fmt::print("{}\n", analysis_json(report).dump(2));
    else
      fmt::print("{}", analysis_text(report));
  });
}

}  // namespace dg::cli
