// How many symmetry candidates analyze verifies and how many symmetries give docking sites: the
// report says what was left out, and --candidates / --site-symmetries reach further. A pipe tree
// of five levels has so many motions between its equal subtrees that, at the defaults, those
// taking one branch level onto the next are neither verified nor examined.

#include "assets/generator/asset.h"
#include "geometry/model_io.h"
#include "support/cli_run.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

// Whether some non-terminal of analyze's JSON summary can derive itself again.
bool has_recursion(const nlohmann::json& summary) {
  std::vector<std::string> names;
  for (const auto& n : summary["nonterminals"]) names.push_back(n["name"].get<std::string>());
  const std::size_t n = names.size();
  auto index = [&](const std::string& name) { return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin()); };
  std::vector<std::vector<char>> reaches(n, std::vector<char>(n, 0));
  for (const auto& p : summary["productions"]) {
    const std::size_t lhs = index(p["lhs"].get<std::string>());
    if (lhs == n) continue;  // the axiom
    for (const auto& c : p["children"]) reaches[lhs][index(c.get<std::string>())] = 1;
  }
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) reaches[i][j] = reaches[i][j] || (reaches[i][k] && reaches[k][j]);
  for (std::size_t i = 0; i < n; ++i)
    if (reaches[i][i]) return true;
  return false;
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("analyze: the report names the candidates and symmetries left out, and the options reach them",
          "[tools][context_free]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-search-limits");
  dg::write_mesh(folder / "tree.obj", dg::assets::make_asset("pipe_tree", {{"depth", 5}}).mesh);
  const std::string model = (folder / "tree.obj").string();

  const dg::test::CliRun plain = dg::test::run_cli("analyze " + model + " -q --json -o " + (folder / "plain").string(), folder);
  INFO(plain.output);
  REQUIRE(plain.status == 0);
  const nlohmann::json plain_summary = nlohmann::json::parse(plain.output);
  CHECK(plain_summary["unverified_candidates"].get<int>() > 0);
  CHECK(plain_summary["unexamined_symmetries"].get<int>() > 0);
  const std::string report = read_text(folder / "plain" / "tree.report.md");
  CHECK(report.find("more were not (`--candidates` verifies more)") != std::string::npos);
  CHECK(report.find("over the top 24 symmetries (one per repetition family") != std::string::npos);
  CHECK(report.find("more not examined: `--site-symmetries` examines more") != std::string::npos);

  // Every candidate verified and twice the symmetries examined: the level-to-level motions give
  // docking sites around the stems of one level that hold those of the next, so the productions
  // recurse (trees of any depth), as they do at the defaults for smaller trees.
  const dg::test::CliRun wide = dg::test::run_cli(
      "analyze " + model + " -q --json --candidates 400 --site-symmetries 48 -o " + (folder / "wide").string(), folder);
  INFO(wide.output);
  REQUIRE(wide.status == 0);
  const nlohmann::json wide_summary = nlohmann::json::parse(wide.output);
  CHECK(wide_summary["unverified_candidates"].get<int>() == 0);
  CHECK(wide_summary["symmetries"].get<int>() > plain_summary["symmetries"].get<int>());
  CHECK(has_recursion(wide_summary));
  CHECK(read_text(folder / "wide" / "tree.report.md").find("more were not (`--candidates`") == std::string::npos);

  const dg::test::CliRun none = dg::test::run_cli("symmetry " + model + " -q --candidates 0", folder);
  CHECK(none.status == 2);
}
