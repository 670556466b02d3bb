// Grid pieces and context-free terminals keep the exemplar's materials, and the grammar file
// keeps them: checked against the material fence's ground truth (tests/support/material_models.h).

#include "grammar/grammar_file.h"
#include "grammar/grid_cut.h"
#include "grammar/material_json.h"
#include "geometry/errors.h"
#include "support/asset_grammar.h"
#include "support/cli_run.h"
#include "support/material_models.h"
#include "synthesis/shape_derivation.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <set>

using dg::Vec3;

namespace {

// fence(4) with materials: grid and context-free rules, analysed once for the tests below.
const dg::ShapeGrammar& fence_grammar() {
  static const dg::ShapeGrammar grammar = dg::test::model_grammar(dg::test::material_fence(4), true);
  return grammar;
}

// Checks that every triangle of `mesh`, moved by `to_model` into the exemplar, carries the
// exemplar's material there; returns the materials seen.
std::set<std::uint32_t> check_materials(const dg::TriangleMesh& mesh, const dg::RigidTransform& to_model = {}) {
  std::set<std::uint32_t> seen;
  if (mesh.triangles.empty()) return seen;
  REQUIRE(mesh.has_materials());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    const Vec3 at = to_model.apply((a + b + c) / 3.0);
    INFO("triangle " << t << " at " << at.transpose());
    CHECK(mesh.materials[t] == dg::test::fence_material_at(at));
    seen.insert(mesh.materials[t]);
  }
  return seen;
}

}  // namespace

TEST_CASE("materials: grid pieces of the material fence keep the exemplar's materials", "[grammar][materials]") {
  const dg::ShapeGrammar& grammar = fence_grammar();
  CHECK(grammar.materials.size() == 3);
  REQUIRE(grammar.grids.size() == 1);
  std::set<std::uint32_t> seen;
  for (const dg::GridPiece& piece : grammar.grids[0].pieces) {
    INFO("piece " << dg::piece_name(piece.classes));
    const auto materials = check_materials(piece.mesh);
    seen.insert(materials.begin(), materials.end());
  }
  CHECK(seen == std::set<std::uint32_t>{dg::test::kWood, dg::test::kMetal, dg::test::kCap});
}

TEST_CASE("materials: context-free terminals and derivations keep the exemplar's materials", "[grammar][materials]") {
  const dg::ShapeGrammar& grammar = fence_grammar();
  const dg::ContextFreeGrammar& cf = grammar.context_free;
  REQUIRE_FALSE(cf.empty());
  check_materials(cf.axiom.terminal);
  for (std::size_t i = 0; i < cf.productions.size(); ++i) {
    INFO("production " << i + 1);
    REQUIRE(cf.productions[i].source_frame);
    check_materials(cf.productions[i].terminal, *cf.productions[i].source_frame);
  }
  // The exemplar's own productions rebuild it with its materials; upright random variants of a
  // fence only slide and turn pieces about z, which keeps every material's ground truth.
  dg::ShapeDerivationOptions options;
  options.exemplar_only = true;
  CHECK(check_materials(dg::derive_shape(cf, grammar.eps, options).mesh).size() == 3);
  options.exemplar_only = false;
  options.up = Vec3::UnitZ();
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    options.seed = seed;
    INFO("seed " << seed);
    check_materials(dg::derive_shape(cf, grammar.eps, options).mesh);
  }
}

TEST_CASE("materials: the grammar file keeps the material list and every piece's materials", "[grammar][materials]") {
  const dg::ShapeGrammar& grammar = fence_grammar();
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-materials-file-test");
  dg::write_grammar(folder / "fence.grammar.json", grammar);
  const dg::ShapeGrammar read = dg::read_grammar(folder / "fence.grammar.json");
  CHECK(read.materials == grammar.materials);
  CHECK(read.exemplar.materials == grammar.exemplar.materials);
  REQUIRE(read.grids.size() == 1);
  REQUIRE(read.grids[0].pieces.size() == grammar.grids[0].pieces.size());
  for (std::size_t p = 0; p < read.grids[0].pieces.size(); ++p)
    CHECK(read.grids[0].pieces[p].mesh.materials == grammar.grids[0].pieces[p].mesh.materials);
  CHECK(read.context_free.axiom.terminal.materials == grammar.context_free.axiom.terminal.materials);
  REQUIRE(read.context_free.productions.size() == grammar.context_free.productions.size());
  for (std::size_t i = 0; i < read.context_free.productions.size(); ++i)
    CHECK(read.context_free.productions[i].terminal.materials == grammar.context_free.productions[i].terminal.materials);

  // Runs that do not cover a piece's triangles are refused with the file's name.
  std::ifstream in(folder / "fence.grammar.json");
  nlohmann::json document = nlohmann::json::parse(in);
  in.close();
  document["grids"][0]["pieces"][0]["material_runs"] = nlohmann::json::array({{0, 1}});
  std::ofstream(folder / "broken.grammar.json") << document.dump();
  CHECK_THROWS_WITH(dg::read_grammar(folder / "broken.grammar.json"), Catch::Contains("material runs cover 1 of"));

  // Without materials the file names none and reads back without any.
  dg::ShapeGrammar plain = grammar;
  plain.materials.clear();
  dg::write_grammar(folder / "plain.grammar.json", plain);
  std::ifstream plain_in(folder / "plain.grammar.json");
  const std::string text((std::istreambuf_iterator<char>(plain_in)), std::istreambuf_iterator<char>());
  CHECK(text.find("material") == std::string::npos);
  const dg::ShapeGrammar plain_read = dg::read_grammar(folder / "plain.grammar.json");
  CHECK(plain_read.materials.empty());
  CHECK_FALSE(plain_read.grids[0].pieces[0].mesh.has_materials());
}

TEST_CASE("materials: the grammar file keeps a material's opacity and rejects one outside 0..1", "[grammar][materials]") {
  std::vector<dg::Material> materials = {{"wall", Vec3(0.9, 0.9, 0.9)}, {"glass", Vec3(0.2, 0.3, 0.4), 0.5}};
  const nlohmann::json list = dg::materials_json(materials);
  CHECK_FALSE(list[0].contains("opacity"));  // opaque materials are written as before
  CHECK(list[1].at("opacity") == 0.5);
  CHECK(dg::read_materials_json(list, "test") == materials);
  nlohmann::json bad = list;
  bad[1]["opacity"] = 1.5;
  CHECK_THROWS_AS(dg::read_materials_json(bad, "test"), dg::InputError);
}
