// Size range of context-free variants (ShapeDerivationOptions::min_size and max_size). The
// three-level pipe tree's grammar lets a leaf cap take the place of the whole tree above the
// root stem (a valid replace: the root stem's docking site has the leaf stems' shape), and lets
// leaves grow whole subtrees, so unrestricted variants range from stubs of an eighth of the
// exemplar's area to trees several times larger. A range keeps every variant inside it and
// still leaves a choice.

#include "synthesis/shape_derivation.h"
#include "synthesis/variants.h"

#include "support/asset_grammar.h"
#include "support/cli_run.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <utility>
#include <vector>

namespace {

// Area of `count` variants (seeds as `generate --seed 1` gives them) over the exemplar's.
std::vector<double> variant_sizes(const dg::ShapeGrammar& grammar, dg::ShapeDerivationOptions options, std::uint64_t count,
                                  std::size_t* changed = nullptr) {
  std::vector<double> sizes;
  for (std::uint64_t i = 0; i < count; ++i) {
    options.seed = dg::variant_seed(1, i);
    const dg::ShapeDerivation d = dg::derive_shape(grammar.context_free, grammar.eps, options);
    sizes.push_back(d.mesh.area() / grammar.exemplar.area());
    if (changed != nullptr && d.changed) ++*changed;
  }
  return sizes;
}

}  // namespace

TEST_CASE("size range: pipe-tree variants keep within the given fractions of the exemplar's area", "[synthesis][variants]") {
  const dg::ShapeGrammar grammar = dg::test::asset_grammar("pipe_tree", {{"depth", 3}}, true);
  REQUIRE_FALSE(grammar.context_free.empty());

  dg::ShapeDerivationOptions any;
  any.min_size = 0.0;
  const std::vector<double> free = variant_sizes(grammar, any, 24);
  CHECK(*std::min_element(free.begin(), free.end()) < 0.2);  // a capped stub
  CHECK(*std::max_element(free.begin(), free.end()) > 1.2);  // a grown tree

  dg::ShapeDerivationOptions ranged;
  ranged.min_size = 0.5;
  ranged.max_size = 1.5;
  CHECK(dg::derivation_has_choice(grammar.context_free, ranged));
  std::size_t changed = 0;
  for (double size : variant_sizes(grammar, ranged, 24, &changed)) {
    CHECK(size > 0.5 - 1e-3);
    CHECK(size < 1.5 + 1e-3);
  }
  CHECK(changed > 0);

  // The default keeps at least half the exemplar and sets no upper limit.
  const std::vector<double> by_default = variant_sizes(grammar, {}, 24);
  CHECK(*std::min_element(by_default.begin(), by_default.end()) > 0.5 - 1e-3);
}

TEST_CASE("size range: generate --min-size and --max-size bound the manifest's sizes, values out of range are errors", "[synthesis][variants]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-size-range-test");
  const dg::test::AnalyzedModel tree = dg::test::analyze_model("pipe_tree_3", folder, "--up z");
  REQUIRE(tree.run.status == 0);
  const std::string grammar = tree.grammar.string();
  const dg::test::CliRun run =
      dg::test::run_cli("generate " + grammar + " --count 8 --min-size 0.6 --max-size 2 -q -o " + (folder / "v").string(), folder);
  REQUIRE(run.status == 0);
  nlohmann::json manifest;
  std::ifstream(folder / "v" / "manifest.json") >> manifest;
  REQUIRE(manifest.at("variants").size() == 8);
  for (const nlohmann::json& variant : manifest.at("variants")) {
    const double size = variant.at("size");
    CHECK(size > 0.6 - 1e-3);
    CHECK(size < 2.0 + 1e-3);
  }
  for (const auto& [option, value] : {std::pair{"--min-size", "1.5"}, {"--min-size", "-0.1"}, {"--max-size", "0.5"}}) {
    INFO(option << " " << value);
    const dg::test::CliRun refused = dg::test::run_cli(
        "generate " + grammar + " " + option + " " + value + " -q -o " + (folder / "w").string(), folder);
    CHECK(refused.status == 2);
    CHECK(refused.output.find(option) != std::string::npos);
  }
}
