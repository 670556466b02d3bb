// `dockgrammar generate GRAMMAR --count N [--seed S] -o DIR [--format obj|ply|glb]`.

#include "tools/dockgrammar/commands.h"

#include "geometry/atomic_file.h"
#include "geometry/errors.h"
#include "geometry/model_io.h"
#include "geometry/point_splats.h"
#include "geometry/render_mesh.h"
#include "geometry/submesh.h"
#include "grammar/grammar_file.h"
#include "synthesis/shape_derivation.h"
#include "tools/dockgrammar/model_options.h"
#include "tools/dockgrammar/number_checks.h"
#include "tools/dockgrammar/output_folder.h"
#include "tools/dockgrammar/output_frame.h"
#include "tools/dockgrammar/pictures.h"
#include "synthesis/variants.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <unistd.h>

namespace dg::cli {

void add_generate_command(CLI::App& app) {
  struct Options {
    std::string grammar;
    std::size_t count = 10;
    std::uint64_t seed = 1;
    std::uint64_t first = 0;
    std::string output;
    std::string format;
    double range_factor = 2.0;
    std::string rules = "auto";
    int max_depth = 24;
    std::size_t max_triangles = 5'000'000;
    double min_size = ShapeDerivationOptions{}.min_size;
    double max_size = ShapeDerivationOptions{}.max_size;
    int threads = 0;
    bool pictures = false;
    bool verify = true;
    std::string up;
    std::string orientation = "upright";
    bool quiet = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "generate", "Write random variants of a grammar (random context-free derivations, or random grid counts) plus DIR/manifest.json");
  command->add_option("GRAMMAR", options->grammar, "Grammar file written by analyze")->required();
  command->add_option("--count", options->count, "Number of variants")->capture_default_str()->check(number_in(1, 1000000));
  command->add_option("--seed", options->seed, "Seed of the batch; variant i depends only on (grammar, seed, i)")->capture_default_str()->check(seed_number());
  command->add_option("--first", options->first, "Index of the first variant (to split a batch across machines)")
      ->capture_default_str()
      ->check(number_in<std::uint64_t>(0, 1'000'000'000'000));
  command->add_option("-o,--output", options->output, "Output folder")->required();
  command->add_option("--format", options->format, "obj, ply or glb (default: obj; ply for a grammar made from a point cloud)")
      ->check(CLI::IsMember({"obj", "ply", "glb"}));
  command->add_option("--range-factor", options->range_factor, "Counts are drawn from [count / F, count * F]")
      ->capture_default_str()
      ->check(number_in(1.0, 100.0));
  command->add_option("--rules", options->rules, "auto (context-free rules when they can change the exemplar under --orientation, else the grid; neither is an error), grid or context-free (with no choice: rebuilds the exemplar)")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "grid", "context-free"}));
  command->add_option("--max-depth", options->max_depth, "Context-free: deeper slots get the exemplar's production")
      ->capture_default_str()
      ->check(number_in(0, 10000));
  command->add_option("--max-triangles", options->max_triangles,
                      "Context-free: after this many triangles (points, for a point-cloud grammar) every slot gets the exemplar's "
                      "production; grid variants: a batch whose largest counts could place more is refused")
      ->capture_default_str()
      ->check(number_in(std::size_t{1}, std::size_t{1'000'000'000}));
  command
      ->add_option("--min-size", options->min_size,
                   "Context-free: every variant keeps at least this fraction of the exemplar's size (surface area; points "
                   "for a point-cloud grammar); productions that would leave less are not drawn")
      ->capture_default_str()
      ->check(number_in(0.0, 1.0));
  command
      ->add_option("--max-size", options->max_size,
                   "Context-free: no variant grows past this multiple of the exemplar's size (default: no limit)")
      ->check(number_in(1.0, 1e9));
  command->add_option("--threads", options->threads, "Worker threads (default: all cores); the files do not depend on it")
      ->check(number_in(0, 4096));
  command->add_flag("--pictures", options->pictures, "Also write a PNG picture of every variant next to it");
  command->add_flag("--verify,!--no-verify", options->verify,
                    "Context-free: check every variant as `verify` does (closed, no self-intersections, r-similar at the "
                    "grammar's r) and draw again when it fails; the exemplar is rebuilt when no draw passes (default: on)");
  add_up_option(*command, options->up, "the axis analyze --up stored in the grammar file, else guessed from the exemplar");
  command
      ->add_option("--orientation", options->orientation,
                   "Context-free: upright (pieces keep the up axis of --up pointing as in the exemplar; they may turn "
                   "about it) or free (any rigid motion the grammar allows, e.g. a window on its side)")
      ->capture_default_str()
      ->check(CLI::IsMember({"upright", "free"}));
  command->add_flag("-q,--quiet", options->quiet, "No progress on stderr");
  command->callback([options] {
    const auto threads = limit_threads(options->threads);
    const ShapeGrammar grammar = read_grammar(options->grammar);
    const bool points = is_point_grammar(grammar);
    const std::string format = !options->format.empty() ? options->format : points ? "ply" : "obj";
    if (points && format != "ply")
      throw InputError(options->grammar + ": the grammar was made from a point cloud, so its variants are point clouds: use --format ply");
    const std::filesystem::path folder(options->output);
    VariantOptions variant_options;
    variant_options.range_factor = options->range_factor;
    variant_options.rules = options->rules == "grid"           ? VariantRules::grid
                            : options->rules == "context-free" ? VariantRules::context_free
                                                               : VariantRules::automatic;
    variant_options.derivation.max_depth = options->max_depth;
    variant_options.derivation.max_triangles = options->max_triangles;
    variant_options.verify = options->verify;
    variant_options.derivation.min_size = options->min_size;
    variant_options.derivation.max_size = options->max_size;
    const MeshRenderOptions picture = picture_options(exemplar_bounds(grammar), options->up.empty() ? grammar.up_axis : options->up);
    if (options->orientation == "upright") variant_options.derivation.up = picture.camera.up.normalized();
    if (!plan_variant(grammar, options->seed, options->first, variant_options).context_free) {
      const std::size_t largest = largest_grid_variant_size(grammar, variant_options);
      if (largest > options->max_triangles)
        throw LimitError(fmt::format("grid variants with counts up to {} times the exemplar's (--range-factor) could place "
                                     "about {} {}, more than --max-triangles {}; lower the one or raise the other",
                                     options->range_factor, largest, points ? "points" : "triangles", options->max_triangles));
    }
    create_output_folder(folder);
    // Model frame -> the mesh files' (the source model's axes; a .glb turned so that up is +y).
    const RigidTransform to_file = file_frame("variant." + format, picture.camera.up.normalized()).after(to_source_frame(grammar));
    const double exemplar_size = points ? static_cast<double>(grammar.exemplar_points.positions.size()) : grammar.exemplar.area();
    std::size_t limited = 0, rebuilt = 0, unchanged = 0, one_grid_only = 0, failed_verify = 0;
    std::string one_grid_reason;
    const bool progress = !options->quiet && ::isatty(STDERR_FILENO);
    nlohmann::json variants = nlohmann::json::array();
    for (std::size_t n = 0; n < options->count; ++n) {
      const std::uint64_t index = options->first + n;
      const VariantPlan plan = plan_variant(grammar, options->seed, index, variant_options);
      const Variant variant = build_variant(grammar, plan, variant_options);
      const TriangleMesh& mesh = variant.mesh;
      const std::string file = fmt::format("variant_{:05}.{}", index, format);
      const std::filesystem::path png = folder / fmt::format("variant_{:05}.png", index);
      if (points) {
        write_point_cloud(folder / file, transformed(variant.points, to_source_frame(grammar)));
        if (options->pictures) write_points_picture(png, variant.points.positions, {}, kSplatRadius * grammar.eps, picture);
      } else {
        write_mesh_with_materials(folder / file, transformed(mesh, to_file), grammar.materials);
        if (options->pictures) write_mesh_picture(png, mesh, material_colors(mesh, grammar.materials), {}, picture);
      }
      nlohmann::json grids = nlohmann::json::object();
      for (std::size_t g = 0; g < variant.grid_counts.size(); ++g) grids[grammar.grids[g].rule.name] = variant.grid_counts[g];
      if (!variant.one_grid_only.empty()) {
        ++one_grid_only;
        one_grid_reason = variant.one_grid_only;
      }
      const ShapeDerivation& d = variant.derivation;
      nlohmann::json productions = nlohmann::json::array();
      for (std::size_t p : d.productions) productions.push_back(p);
      if (d.depth_limited || d.triangle_limited) ++limited;
      if (d.restarts > variant_options.derivation.restarts) ++rebuilt;
      if (variant.verify_fallback) ++failed_verify;
      else if (!variant.changed) ++unchanged;
      variants.push_back({{"index", index},
                          {"file", file},
                          {"seed", plan.seed},
                          {"rules", plan.context_free ? "context-free" : "grid"},
                          {"grids", grids},
                          {"productions", productions},
                          {"changed", variant.changed},
                          {"failed_verify", variant.failed_verify},
                          {"r_similar", variant.r_similar ? nlohmann::json(*variant.r_similar) : nlohmann::json(nullptr)},
                          {"size", (points ? static_cast<double>(variant.points.positions.size()) : mesh.area()) / exemplar_size},
                          {"collisions_retried", d.collisions_retried},
                          {"fallbacks", d.fallbacks},
                          {"restarts", d.restarts},
                          {"depth_limited", d.depth_limited},
                          {"triangle_limited", d.triangle_limited},
                          {points ? "points" : "triangles", points ? variant.points.positions.size() : mesh.triangles.size()}});
      if (progress) fmt::print(stderr, "\r\033[Kvariant {}/{}", n + 1, options->count);
    }
    if (progress) fmt::print(stderr, "\n");
    if (limited > 0 && !options->quiet)
      fmt::print(stderr, "note: {} variant(s) reached --max-depth or --max-triangles; their deeper slots kept the exemplar's geometry\n",
                 limited);
    if (rebuilt > 0 && !options->quiet)
      fmt::print(stderr,
                 "note: {} variant(s) are the exemplar rebuilt: {} derivations in a row left some exemplar piece no room\n",
                 rebuilt, variant_options.derivation.restarts + 1);
    if (unchanged > 0 && !options->quiet)
      fmt::print(stderr,
                 "note: {} variant(s) have the exemplar's shape: in up to 9 draws each, the rules gave nothing else\n",
                 unchanged);
    if (failed_verify > 0 && !options->quiet)
      fmt::print(stderr, "note: {} variant(s) are the exemplar rebuilt: every draw failed verify (not r-similar, open or "
                         "self-intersecting)\n", failed_verify);
    if (one_grid_only > 0 && !options->quiet)
      fmt::print(stderr, "note: {} variant(s) resize one grid only, the others keep the exemplar's counts: {}\n", one_grid_only,
                 one_grid_reason);
    const nlohmann::json manifest = {{"grammar", options->grammar}, {"seed", options->seed}, {"first", options->first},
                                     {"count", options->count},     {"orientation", options->orientation},
                                     {"variants", variants}};
    write_file_atomically(folder / "manifest.json", [&](std::ostream& out) { out << manifest.dump(2) << '\n'; }, false);
    if (!options->quiet) fmt::print(stderr, "wrote {} variants and manifest.json to {}\n", options->count, folder.string());
  });
}

}  // namespace dg::cli
