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
#include "support/shapes.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>

namespace {

// A closed prism of `sides` sides around the z axis, radius `radius`, from z0 to z1.
dg::TriangleMesh prism(double radius, double z0, double z1, int sides) {
  dg::TriangleMesh mesh;
  for (int i = 0; i < sides; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / sides;
    mesh.positions.push_back(dg::Vec3(radius * std::cos(angle), radius * std::sin(angle), z0));
    mesh.positions.push_back(dg::Vec3(radius * std::cos(angle), radius * std::sin(angle), z1));
  }
  const auto bottom = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.push_back(dg::Vec3(0, 0, z0));
  mesh.positions.push_back(dg::Vec3(0, 0, z1));
  for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(sides); ++i) {
    const std::uint32_t j = (i + 1) % static_cast<std::uint32_t>(sides);
    mesh.triangles.push_back({2 * i, 2 * j, 2 * j + 1});
    mesh.triangles.push_back({2 * i, 2 * j + 1, 2 * i + 1});
    mesh.triangles.push_back({bottom, 2 * j, 2 * i});
    mesh.triangles.push_back({bottom + 1, 2 * i + 1, 2 * j + 1});
  }
  return mesh;
}

// A round table on a pedestal with six chairs around it, z up (metres): each chair's seat, four
// legs and back are boxes modelled apart, the legs' tops touching the seat's underside and the
// back standing on the seat, as furniture is often built.
dg::TriangleMesh round_table_with_six_chairs() {
  dg::TriangleMesh table = prism(0.65, 0.72, 0.76, 24);
  dg::test::append(table, prism(0.06, 0.0, 0.72, 24));
  for (int k = 0; k < 6; ++k) {
    dg::TriangleMesh chair = dg::test::make_box(dg::Vec3(0.75, -0.2, 0.42), dg::Vec3(1.15, 0.2, 0.46));
    for (const double dx : {-0.17, 0.17})
      for (const double dy : {-0.17, 0.17})
        dg::test::append(chair, dg::test::make_box(dg::Vec3(0.93 + dx, dy - 0.02, 0), dg::Vec3(0.97 + dx, dy + 0.02, 0.42)));
    dg::test::append(chair, dg::test::make_box(dg::Vec3(1.12, -0.2, 0.46), dg::Vec3(1.16, 0.2, 0.9)));
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(k * std::numbers::pi / 3.0, dg::Vec3::UnitZ()).toRotationMatrix();
    for (dg::Vec3& p : chair.positions) p = turn * p;
    dg::test::append(table, chair);
  }
  return table;
}

// `dockgrammar verify` of a variant's mesh against the grammar's exemplar at the grammar's r.
bool passes_verify(const dg::ShapeGrammar& grammar, const dg::TriangleMesh& mesh) {
  dg::Model exemplar, candidate;
  exemplar.mesh = grammar.exemplar;
  candidate.mesh = mesh;
  dg::VerifyOptions options;
  options.r = grammar.r;
  return dg::verify_models(std::move(exemplar), std::move(candidate), options).pass;
}

// Variants 0 .. count - 1 of seed 1, each checked to pass verify without the exemplar rebuilt.
std::vector<dg::Variant> verified_variants(const dg::ShapeGrammar& grammar, const dg::VariantOptions& options, std::uint64_t count) {
  std::vector<dg::Variant> variants;
  for (std::uint64_t i = 0; i < count; ++i) {
    variants.push_back(dg::build_variant(grammar, dg::plan_variant(grammar, 1, i, options), options));
    INFO("variant " << i << ": " << variants.back().failed_verify << " draws failed verify");
    CHECK(passes_verify(grammar, variants.back().mesh));
    CHECK_FALSE(variants.back().verify_fallback);
  }
  return variants;
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
  for (const dg::Variant& variant : verified_variants(grammar, options, 24))
    if (variant.changed) {
      ++changed;
      REQUIRE(variant.r_similar);
      CHECK(*variant.r_similar >= dg::VerifyOptions{}.min_similar_fraction);
    }
  CHECK(changed >= 20);
}

// The pieces' seams cross the legs' tops and the seats' undersides along the same lines, so
// cutting and welding once joined the two at those seams: every variant had non-manifold edges
// there, failed verify in all its draws and was the exemplar rebuilt.
TEST_CASE("verified variants: a table whose chairs' legs touch their seats gives closed variants", "[synthesis][variants][verify]") {
  dg::Model model;
  model.mesh = round_table_with_six_chairs();
  const dg::ShapeGrammar grammar = dg::test::model_grammar(std::move(model), true);
  REQUIRE_FALSE(grammar.context_free.empty());
  dg::VariantOptions options;
  options.rules = dg::VariantRules::context_free;
  options.derivation.up = dg::Vec3::UnitZ();
  options.verify = true;
  const std::vector<dg::Variant> variants = verified_variants(grammar, options, 4);
  CHECK(std::count_if(variants.begin(), variants.end(), [](const dg::Variant& v) { return v.changed; }) >= 3);
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
