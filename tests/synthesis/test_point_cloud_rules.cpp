// Context-free rules of a point cloud: the pieces are the cloud's own points, split by the
// docking sites' seams. Rebuilding the exemplar from its productions gives back the sampled
// surface, and random derivations stay r-similar to the scan.

#include "synthesis/shape_derivation.h"
#include "synthesis/verify.h"

#include "assets/generator/asset.h"
#include "geometry/same_surface.h"
#include "geometry/surface_sampling.h"
#include "grammar/context_free.h"
#include "grammar/grammar_file.h"
#include "geometry/model_io.h"
#include "support/cli_run.h"
#include "support/corpus.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

namespace {

struct CloudGrammar {
  dg::PointCloud cloud;
  double eps = 0.0;
  dg::ContextFreeGrammar grammar;
};

// The context-free grammar of 400,000 points drawn on the 2 x 3 facade (no normals, as a scan).
CloudGrammar cloud_grammar() {
  dg::Model model;
  model.cloud.positions = dg::sample_surface(dg::assets::make_asset("facade", {{"columns", 2}, {"rows", 3}}).mesh, 400000, 3).positions;
  const dg::PreparedModel prepared = dg::prepare_model(std::move(model));
  const dg::SymmetryResult symmetries = dg::detect_symmetries(prepared);
  const dg::DockingSiteResult docking = dg::find_docking_sites(prepared, symmetries);
  return {prepared.model.cloud, prepared.surface.eps(), dg::build_context_free_grammar(prepared, docking, {})};
}

// Whether `derived` samples the cloud's surface (same_points within eps) with as many points
// within 1 %.
bool rebuilt_like_the_cloud(const dg::PointCloud& derived, const CloudGrammar& g) {
  const auto n = static_cast<double>(g.cloud.positions.size());
  return dg::same_points(derived, g.cloud, g.eps) && std::abs(static_cast<double>(derived.positions.size()) - n) <= 0.01 * n;
}

}  // namespace

TEST_CASE("context-free rules of a point cloud rebuild its points and derive r-similar variants", "[synthesis][cloud]") {
  const CloudGrammar g = cloud_grammar();
  REQUIRE(!g.grammar.empty());
  CHECK(g.grammar.of_points());
  CHECK(g.grammar.axiom.terminal.triangles.empty());
  for (const dg::ShapeProduction& p : g.grammar.productions) {
    CHECK(p.terminal.triangles.empty());
    CHECK((!p.terminal_points.positions.empty() || !p.children.empty()));
  }
  // Some non-terminal offers a choice (another production of it).
  dg::ShapeDerivationOptions options;
  CHECK(dg::derivation_has_choice(g.grammar, options));

  // The exemplar's own productions give back the cloud's surface (a location whose production has
  // the shape of one cut elsewhere takes that one's points).
  options.exemplar_only = true;
  const dg::ShapeDerivation rebuilt = dg::derive_shape(g.grammar, g.eps, options);
  CHECK(rebuilt.mesh.triangles.empty());
  CHECK(rebuilt.point_nonterminal.size() == rebuilt.points.positions.size());
  CHECK(rebuilt_like_the_cloud(rebuilt.points, g));

  // Random derivations: deterministic per seed, changed, and r-similar to the cloud.
  options.exemplar_only = false;
  std::size_t changed = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    options.seed = seed;
    const dg::ShapeDerivation derived = dg::derive_shape(g.grammar, g.eps, options);
    const dg::ShapeDerivation again = dg::derive_shape(g.grammar, g.eps, options);
    CHECK(derived.points.positions == again.points.positions);
    CHECK(derived.restarts <= options.restarts);  // not the exemplar rebuilt after every start failed
    if (!derived.changed) continue;
    ++changed;
    dg::Model exemplar, candidate;
    exemplar.cloud = g.cloud;
    candidate.cloud = derived.points;
    dg::VerifyOptions verify;
    verify.similarity.samples = 300;
    const dg::VerifyReport report = dg::verify_models(std::move(exemplar), std::move(candidate), verify);
    CHECK(report.pass);
  }
  CHECK(changed > 0);
}

TEST_CASE("a point cloud's context-free rules survive the grammar file", "[synthesis][cloud]") {
  const CloudGrammar g = cloud_grammar();
  REQUIRE(!g.grammar.empty());
  dg::ShapeGrammar grammar;
  grammar.source_name = "facade_points.ply";
  grammar.source_hash = "0";
  grammar.r = 4.0 * g.eps;
  grammar.eps = g.eps;
  grammar.exemplar_points = g.cloud;
  grammar.context_free = g.grammar;
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-cloud-rules");
  dg::write_grammar(folder / "cloud.grammar.json", grammar);
  const dg::ShapeGrammar read = dg::read_grammar(folder / "cloud.grammar.json");
  REQUIRE(read.context_free.productions.size() == g.grammar.productions.size());
  CHECK(read.context_free.of_points());
  CHECK(read.context_free.axiom.terminal_points.positions.size() == g.grammar.axiom.terminal_points.positions.size());
  for (std::size_t i = 0; i < g.grammar.productions.size(); ++i) {
    CHECK(read.context_free.productions[i].terminal_points.positions.size() ==
          g.grammar.productions[i].terminal_points.positions.size());
    CHECK(read.context_free.productions[i].children.size() == g.grammar.productions[i].children.size());
  }
  // Placements come back within rounding (the file stores 4x4 matrices); the exemplar's own
  // productions still give back the cloud.
  for (std::size_t i = 0; i < g.grammar.productions.size(); ++i)
    for (std::size_t c = 0; c < g.grammar.productions[i].children.size(); ++c)
      CHECK((read.context_free.productions[i].children[c].placement.matrix() - g.grammar.productions[i].children[c].placement.matrix())
                .cwiseAbs()
                .maxCoeff() < 1e-12 * g.eps);
  dg::ShapeDerivationOptions options;
  options.exemplar_only = true;
  CHECK(rebuilt_like_the_cloud(dg::derive_shape(read.context_free, read.eps, options).points, g));
  // Terminals are stored as indices of the exemplar's points (4 bytes a point) and come back as
  // the same points.
  std::ifstream file(folder / "cloud.grammar.json");
  const nlohmann::json document = nlohmann::json::parse(file);
  const nlohmann::json& first = document["productions"][0];
  CHECK(first["terminal_of"] == "exemplar_points");
  const std::filesystem::path indices = folder / first["terminal"].get<std::string>();
  CHECK(indices.extension() == ".u32");
  CHECK(std::filesystem::file_size(indices) == 4 * g.grammar.productions[0].terminal_points.positions.size());
  const dg::PointCloud& before = g.grammar.productions[0].terminal_points;
  const dg::PointCloud& after = read.context_free.productions[0].terminal_points;
  REQUIRE(after.positions.size() == before.positions.size());
  double moved = 0.0;
  for (std::size_t i = 0; i < before.positions.size(); ++i) moved = std::max(moved, (after.positions[i] - before.positions[i]).norm());
  CHECK(moved < 1e-9 * g.eps);
  // Broken index sidecars and a missing frame are clear input errors.
  std::ofstream(indices, std::ios::binary | std::ios::app).write("\xff\xff\xff\x7f", 4);
  CHECK_THROWS_WITH(dg::read_grammar(folder / "cloud.grammar.json"), Catch::Contains("names point"));
  std::ofstream(indices, std::ios::binary | std::ios::app).write("\x01", 1);
  CHECK_THROWS_WITH(dg::read_grammar(folder / "cloud.grammar.json"), Catch::Contains("not a list of 4-byte point indices"));
  nlohmann::json frameless = document;
  frameless["productions"][0].erase("source_frame");
  std::ofstream(folder / "frameless.grammar.json") << frameless.dump();
  CHECK_THROWS_WITH(dg::read_grammar(folder / "frameless.grammar.json"), Catch::Contains("with a source_frame"));
  // Without the indices (a grammar built in code), terminals are written as points.
  for (dg::ShapeProduction& p : grammar.context_free.productions) p.terminal_source_points.clear();
  grammar.context_free.axiom.terminal_source_points.clear();
  dg::write_grammar(folder / "plain.grammar.json", grammar);
  const dg::ShapeGrammar plain = dg::read_grammar(folder / "plain.grammar.json");
  CHECK(plain.context_free.productions[0].terminal_points.positions == before.positions);
  std::filesystem::remove_all(folder);
}

TEST_CASE("a point cloud drawn on the Kenney metal gate derives variants r-similar to it", "[synthesis][cloud][corpus]") {
  // Its stakes cross many docking sites; dockers that would meet the rest of the gate otherwise
  // than at their own location (a long stake swapped for a short tip) are not used.
  const auto path = dg::test::corpus_file_if_present("meshes/arch-kenney-castle-metalgate/metal_gate.obj");
  if (!path) return;
  dg::Model model;
  model.cloud.positions = dg::sample_surface(dg::read_model(*path).mesh, 300000, 1).positions;
  const dg::PreparedModel prepared = dg::prepare_model(std::move(model));
  const dg::SymmetryResult symmetries = dg::detect_symmetries(prepared);
  const dg::ContextFreeGrammar grammar =
      dg::build_context_free_grammar(prepared, dg::find_docking_sites(prepared, symmetries), {});
  REQUIRE(!grammar.empty());
  std::size_t changed = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    dg::ShapeDerivationOptions options;
    options.seed = seed;
    dg::ShapeDerivation derived = dg::derive_shape(grammar, prepared.surface.eps(), options);
    if (!derived.changed) continue;
    ++changed;
    dg::Model exemplar, candidate;
    exemplar.cloud = prepared.model.cloud;
    candidate.cloud = std::move(derived.points);
    dg::VerifyOptions verify;
    verify.similarity.samples = 300;
    CHECK(dg::verify_models(std::move(exemplar), std::move(candidate), verify).pass);
  }
  CHECK(changed > 0);
}

