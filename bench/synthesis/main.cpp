// dockgrammar-bench-synthesis: time of one random context-free variant (derivation, collision
// checks, welding; no file output) on generated pipe trees and fences of growing size, of a
// facade grid resize to 20 x 20, of verify per 100k candidate triangles, and of verify of two
// point clouds (scans of the 3 x 4 and 5 x 7 facades). Prints a Markdown table for
// bench/results.md.

#include "assets/generator/asset.h"
#include "geometry/stopwatch.h"
#include "grammar/context_free.h"
#include "grammar/docking_sites.h"
#include "geometry/surface_sampling.h"
#include "grammar/grid_cut.h"
#include "grammar/grid_rules.h"
#include "synthesis/grid_resize.h"
#include "synthesis/shape_derivation.h"
#include "synthesis/verify.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <tbb/global_control.h>

#include <vector>

namespace {

struct Analysed {
  dg::PreparedModel prepared;
  dg::SymmetryResult symmetries;
};

Analysed analyse(const std::string& asset, const nlohmann::json& parameters, std::size_t triangles) {
  dg::Model model;
  model.mesh = dg::assets::make_asset_with_triangles(asset, parameters, triangles).mesh;
  Analysed a{dg::prepare_model(std::move(model)), {}};
  a.symmetries = dg::detect_symmetries(a.prepared);
  return a;
}

void variants_row(const std::string& asset, const nlohmann::json& parameters, std::size_t triangles, int count) {
  const Analysed a = analyse(asset, parameters, triangles);
  dg::Stopwatch stopwatch;
  const dg::DockingSiteResult sites = dg::find_docking_sites(a.prepared, a.symmetries);
  const dg::ContextFreeGrammar grammar = dg::build_context_free_grammar(a.prepared, sites, {});
  const double build_seconds = stopwatch.lap();
  if (grammar.empty()) {
    fmt::print("| {} | {} | no context-free rules | | | |\n", asset, a.prepared.model.mesh.triangles.size());
    return;
  }
  std::size_t total_triangles = 0, retried = 0;
  for (int i = 0; i < count; ++i) {
    dg::ShapeDerivationOptions options;
    options.seed = static_cast<std::uint64_t>(i + 1);
    const dg::ShapeDerivation d = dg::derive_shape(grammar, a.prepared.surface.eps(), options);
    total_triangles += d.mesh.triangles.size();
    retried += d.collisions_retried;
  }
  const double seconds = stopwatch.lap();
  fmt::print("| {} | {} | {:.2f} | {} | {:.0f} | {:.1f} | {} |\n", asset, a.prepared.model.mesh.triangles.size(), build_seconds,
             count, static_cast<double>(total_triangles) / count, 1000.0 * seconds / count, retried);
}

void print_variants_table(const std::vector<std::size_t>& sizes, int count, int threads) {
  fmt::print("Random context-free variants ({} thread(s); derivation + Embree collision checks + welding, no file output)\n\n",
             threads);
  fmt::print("| exemplar | triangles | docking sites + rules s | variants | mean variant triangles | ms per variant | retried choices |\n");
  fmt::print("|---|---|---|---|---|---|---|\n");
  for (std::size_t size : sizes) {
    variants_row("pipe_tree", {{"depth", 3}}, size, count);
    variants_row("fence", {{"n", 4}}, size, count);
  }
}

// Resizes facade(3, 4) of about `triangles` triangles to 20 x 20 and verifies the result
// against it unless `skip_verify`.
void facade_resize_rows(std::size_t triangles, bool skip_verify) {
  const Analysed facade = analyse("facade", {{"columns", 3}, {"rows", 4}}, triangles);
  const std::vector<dg::GridRule> grids = dg::find_grids(facade.prepared, facade.symmetries);
  if (grids.empty() || grids.front().directions.size() != 2) {
    fmt::print("\nThe facade gave no 2-grid: no resize figures.\n");
    return;
  }
  const double eps = facade.prepared.surface.eps();
  const auto pieces = dg::cut_grid_pieces(facade.prepared.model.mesh, grids.front(), eps);
  dg::Stopwatch stopwatch;
  const dg::TriangleMesh resized = dg::resize_grid(grids.front(), pieces, {20, 20}, eps);
  const double resize_seconds = stopwatch.lap();
  fmt::print("\nResize of a {}-triangle facade 3x4 to 20 x 20: {:.2f} s ({} triangles).\n",
             facade.prepared.model.mesh.triangles.size(), resize_seconds, resized.triangles.size());
  if (skip_verify) return;
  dg::Model exemplar, candidate;
  exemplar.mesh = facade.prepared.model.mesh;
  candidate.mesh = resized;
  stopwatch.lap();
  const dg::VerifyReport report = dg::verify_models(std::move(exemplar), std::move(candidate));
  const double verify_seconds = stopwatch.lap();
  fmt::print("verify of it: {:.2f} s, {:.2f} s per 100k candidate triangles ({}, {} of {} samples r-similar).\n",
             verify_seconds, verify_seconds * 1e5 / static_cast<double>(resized.triangles.size()),
             report.pass ? "pass" : "FAIL", report.similarity.similar, report.similarity.samples);
}

// Verifies a scan of facade(5, 7) against a scan of facade(3, 4) of `points` points (the larger
// one as dense: 2.2 times the points).
void cloud_verify_row(std::size_t points) {
  auto scan = [](int columns, int rows, std::size_t count, std::uint64_t seed) {
    dg::Model model;
    model.cloud = dg::sample_surface(dg::assets::make_asset("facade", {{"columns", columns}, {"rows", rows}}).mesh, count, seed);
    return model;
  };
  dg::Model exemplar = scan(3, 4, points, 1), candidate = scan(5, 7, points * 22 / 10, 2);
  dg::Stopwatch stopwatch;
  const dg::VerifyReport report = dg::verify_models(std::move(exemplar), std::move(candidate));
  fmt::print("verify of a {}-point scan of the facade 5x7 against a {}-point scan of the 3x4: {:.2f} s ({}, {} of {} samples "
             "r-similar).\n",
             points * 22 / 10, points, stopwatch.lap(), report.pass ? "pass" : "FAIL", report.similarity.similar,
             report.similarity.samples);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"dockgrammar-bench-synthesis: variants, grid resize and verify timings"};
  std::vector<std::size_t> sizes{10000, 100000, 500000};
  int count = 10;
  int threads = 1;
  std::size_t facade_triangles = 100000;
  std::size_t cloud_points = 200000;
  bool skip_variants = false, skip_verify = false;
  app.add_option("--sizes", sizes, "Target triangle counts of the exemplars")->delimiter(',');
  app.add_option("--count", count, "Variants per exemplar");
  app.add_option("--threads", threads, "Worker threads");
  app.add_option("--facade-triangles", facade_triangles, "Target triangle count of the facade 3x4 resized to 20 x 20");
  app.add_flag("--skip-variants", skip_variants, "No variant table (only the facade resize and its verify)");
  app.add_flag("--skip-verify", skip_verify, "No verify of the resized facade and of the point clouds");
  app.add_option("--cloud-points", cloud_points, "Points of the 3x4 facade's scan in the point-cloud verify");
  CLI11_PARSE(app, argc, argv);
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  if (!skip_variants) print_variants_table(sizes, count, threads);
  facade_resize_rows(facade_triangles, skip_verify);
  if (!skip_verify) cloud_verify_row(cloud_points);
  return 0;
}
