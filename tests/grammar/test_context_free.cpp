#include "grammar/context_free.h"
#include "grammar/docking_sites.h"
#include "grammar/grammar_file.h"
#include "geometry/errors.h"

#include "assets/generator/asset.h"
#include "geometry/topology.h"
#include "support/mesh_distance.h"
#include "synthesis/shape_derivation.h"
#include "synthesis/verify.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <set>
#include <fstream>
#include <iterator>

namespace {

struct Analysed {
  dg::PreparedModel prepared;
  dg::SymmetryResult symmetries;
  dg::DockingSiteResult sites;
  dg::ContextFreeGrammar grammar;
};

Analysed analyse(const std::string& asset, const nlohmann::json& parameters) {
  dg::Model model;
  model.mesh = dg::assets::make_asset(asset, parameters).mesh;
  Analysed a{dg::prepare_model(std::move(model)), {}, {}, {}};
  a.symmetries = dg::detect_symmetries(a.prepared);
  a.sites = dg::find_docking_sites(a.prepared, a.symmetries);
  a.grammar = dg::build_context_free_grammar(a.prepared, a.sites, {});
  return a;
}

}  // namespace

TEST_CASE("context-free grammar: exemplar productions rebuild the exemplar", "[grammar][context_free]") {
  for (const auto& [asset, parameters] :
       std::vector<std::pair<std::string, nlohmann::json>>{{"fence", {{"n", 4}}}, {"pipe_tree", {{"depth", 3}}}}) {
    INFO(asset);
    const Analysed a = analyse(asset, parameters);
    REQUIRE_FALSE(a.grammar.empty());
    dg::ShapeDerivationOptions options;
    options.exemplar_only = true;
    const dg::ShapeDerivation d = dg::derive_shape(a.grammar, a.prepared.surface.eps(), options);
    CHECK(d.mesh.area() == Approx(a.prepared.model.mesh.area()).epsilon(1e-3));
    CHECK(dg::test::hausdorff_distance(d.mesh, a.prepared.model.mesh) < a.prepared.surface.eps());
    CHECK(dg::is_closed_and_oriented(d.mesh));
  }
}

TEST_CASE("context-free grammar: fence variants vary in length, stay closed and seeded", "[grammar][context_free]") {
  const Analysed a = analyse("fence", {{"n", 4}});
  REQUIRE_FALSE(a.grammar.empty());
  const double eps = a.prepared.surface.eps();
  std::set<std::size_t> sizes;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    dg::ShapeDerivationOptions options;
    options.seed = seed;
    const dg::ShapeDerivation d = dg::derive_shape(a.grammar, eps, options);
    INFO("seed " << seed);
    CHECK(dg::is_closed_and_oriented(d.mesh));
    sizes.insert(d.mesh.triangles.size());
    const dg::ShapeDerivation again = dg::derive_shape(a.grammar, eps, options);
    CHECK(again.mesh.positions == d.mesh.positions);
    CHECK(again.productions == d.productions);
  }
  CHECK(sizes.size() >= 3);  // fences of different lengths
}

TEST_CASE("context-free grammar survives the grammar file", "[grammar][context_free]") {
  const Analysed a = analyse("fence", {{"n", 4}});
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "dockgrammar-cf-file-test";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  dg::ShapeGrammar grammar;
  grammar.source_name = "fence.obj";
  grammar.source_hash = "0";
  grammar.r = a.prepared.surface.r();
  grammar.eps = a.prepared.surface.eps();
  grammar.exemplar = a.prepared.model.mesh;
  grammar.context_free = a.grammar;
  const auto path = folder / "fence.grammar.json";
  dg::write_grammar(path, grammar);
  const dg::ShapeGrammar read = dg::read_grammar(path);
  REQUIRE(read.context_free.productions.size() == a.grammar.productions.size());
  REQUIRE(read.context_free.nonterminals.size() == a.grammar.nonterminals.size());
  dg::ShapeDerivationOptions options;
  options.seed = 5;
  const dg::ShapeDerivation before = dg::derive_shape(a.grammar, grammar.eps, options);
  const dg::ShapeDerivation after = dg::derive_shape(read.context_free, grammar.eps, options);
  CHECK(before.productions == after.productions);
  CHECK(dg::test::hausdorff_distance(before.mesh, after.mesh) < 1e-9);

  // A production naming a non-terminal that does not exist is a clear error.
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string name = "\"nonterminal\": \"" + a.grammar.nonterminals.front().name + "\"";
  const auto at = text.find(name);
  REQUIRE(at != std::string::npos);
  text.replace(at, name.size(), "\"nonterminal\": \"N999\"");
  std::ofstream(folder / "broken.grammar.json") << text;
  std::filesystem::copy(folder / "fence.grammar.pieces", folder / "broken.grammar.pieces");
  try {
    dg::read_grammar(folder / "broken.grammar.json");
    FAIL("no error for an unknown non-terminal");
  } catch (const dg::InputError& e) {
    CHECK(std::string(e.what()).find("N999") != std::string::npos);
  }
  std::filesystem::remove_all(folder);
}

TEST_CASE("20 random pipe-tree variants: closed, no self-intersections, verify passes", "[grammar][context_free][verify]") {
  const Analysed a = analyse("pipe_tree", {{"depth", 3}});
  REQUIRE_FALSE(a.grammar.empty());
  std::set<std::size_t> sizes;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    dg::ShapeDerivationOptions options;
    options.seed = seed;
    const dg::ShapeDerivation d = dg::derive_shape(a.grammar, a.prepared.surface.eps(), options);
    sizes.insert(d.mesh.triangles.size());
    dg::Model exemplar, candidate;
    exemplar.mesh = a.prepared.model.mesh;
    candidate.mesh = d.mesh;
    const dg::VerifyReport report = dg::verify_models(std::move(exemplar), std::move(candidate));
    INFO("seed " << seed << ": " << report.similarity.similar << " of " << report.similarity.samples << " samples r-similar");
    CHECK(report.candidate.closed);
    CHECK_FALSE(report.candidate.self_intersects);
    CHECK(report.pass);
  }
  CHECK(sizes.size() >= 3);  // trees of different sizes
}
