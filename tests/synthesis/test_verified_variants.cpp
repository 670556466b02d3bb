// Verified context-free variants (VariantOptions::verify). Derived in any orientation, some
// variants of the spiral stairs are not r-similar to them: pieces turned upside down put steps
// of unrelated places within r of each other without touching, which the collision test allows
// (7 of 60 of `generate --orientation free --min-size 0 --no-verify` fail `verify`). With the
// check every variant passes an independent verify; a check no change can pass (r as large as
// the stairs) gives the exemplar rebuilt.

#include "synthesis/variants.h"
#include "synthesis/verify.h"

#include "support/asset_grammar.h"
#include "support/cli_run.h"
#include "support/mesh_distance.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fstream>

namespace {

// `dockgrammar verify` of a variant's mesh against the grammar's exemplar at the grammar's r.
bool passes_verify(const dg::ShapeGrammar& grammar, const dg::TriangleMesh& mesh) {
  dg::Model exemplar, candidate;
  exemplar.mesh = grammar.exemplar;
  candidate.mesh = mesh;
  dg::VerifyOptions options;
  options.r = grammar.r;
  return dg::verify_models(std::move(exemplar), std::move(candidate), options).pass;
}

}  // namespace

TEST_CASE("verified variants: spiral stairs derived in any orientation all pass verify", "[synthesis][variants][verify]") {
  const dg::ShapeGrammar grammar = dg::test::asset_grammar("spiral_stairs", {{"steps", 12}}, true);
  REQUIRE_FALSE(grammar.context_free.empty());
  dg::VariantOptions options;
  options.rules = dg::VariantRules::context_free;
  options.derivation.min_size = 0.0;
  options.verify = true;
  std::size_t changed = 0;
  for (std::uint64_t i = 0; i < 24; ++i) {
    const dg::Variant variant = dg::build_variant(grammar, dg::plan_variant(grammar, 1, i, options), options);
    INFO("variant " << i << ": " << variant.failed_verify << " draws failed verify");
    CHECK(passes_verify(grammar, variant.mesh));
    CHECK_FALSE(variant.verify_fallback);
    if (variant.changed) {
      ++changed;
      REQUIRE(variant.r_similar);
      CHECK(*variant.r_similar >= dg::VerifyOptions{}.min_similar_fraction);
    }
  }
  CHECK(changed >= 20);
}

TEST_CASE("verified variants: when no draw can pass, the variant is the exemplar rebuilt", "[synthesis][variants][verify]") {
  dg::ShapeGrammar grammar = dg::test::asset_grammar("spiral_stairs", {{"steps", 12}}, true);
  // At an r larger than the stairs every changed model fails r-similarity.
  grammar.r = 10.0 * grammar.exemplar.bounds().size().maxCoeff();
  dg::VariantOptions options;
  options.rules = dg::VariantRules::context_free;
  options.verify = true;
  const dg::Variant variant = dg::build_variant(grammar, dg::plan_variant(grammar, 1, 0, options), options);
  CHECK(variant.verify_fallback);
  CHECK_FALSE(variant.changed);
  CHECK(variant.failed_verify == 9);
  CHECK(variant.mesh.area() == Approx(grammar.exemplar.area()).epsilon(1e-3));
  CHECK(dg::test::hausdorff_distance(variant.mesh, grammar.exemplar) < grammar.eps);
}

TEST_CASE("verified variants: generate checks context-free variants unless --no-verify, and the manifest says how they fared",
          "[synthesis][variants][verify]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-verified-variants-test");
  const dg::test::AnalyzedModel stairs = dg::test::analyze_model("spiral_stairs_12", folder, "--up z");
  REQUIRE(stairs.run.status == 0);
  auto manifest_of = [&](const std::string& options, const std::string& name) {
    const std::string command = "generate " + stairs.grammar.string() + " --count 4 --rules context-free --orientation free " +
                                options + " -q -o " + (folder / name).string();
    REQUIRE(dg::test::run_cli(command, folder).status == 0);
    nlohmann::json manifest;
    std::ifstream(folder / name / "manifest.json") >> manifest;
    return manifest;
  };
  const nlohmann::json checked = manifest_of("", "checked"), unchecked = manifest_of("--no-verify", "unchecked");
  for (const nlohmann::json& variant : checked.at("variants")) {
    CHECK(variant.at("failed_verify").get<std::size_t>() <= 9);
    if (variant.at("changed").get<bool>()) CHECK(variant.at("r_similar").get<double>() >= dg::VerifyOptions{}.min_similar_fraction);
  }
  for (const nlohmann::json& variant : unchecked.at("variants")) {
    CHECK(variant.at("r_similar").is_null());
    CHECK(variant.at("failed_verify") == 0);
  }
}
