// End-to-end runs of `dockgrammar grow`.

#include "support/cli_run.h"

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;

dg::test::CliRun grow(const std::string& arguments, const fs::path& folder) {
  return dg::test::run_cli("grow " + arguments, folder);
}

void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace

TEST_CASE("grow renders a scene, reports counts as JSON, regrows after edits, and rejects bad scenes", "[growth][cli]") {
  const fs::path folder = dg::test::fresh_folder("dockgrammar-grow-cli-test");
  const std::string scenes = std::string(DOCKGRAMMAR_SOURCE_DIR) + "/assets/scenes/";

  dg::test::CliRun ok = grow(scenes + "palm.json -o " + (folder / "palm.svg").string() + " --json", folder);
  REQUIRE(ok.status == 0);
  const nlohmann::json report = nlohmann::json::parse(ok.output);
  CHECK(report["tokens_used"] == 8);
  CHECK(report["guides"].size() == 9);
  CHECK(report["guides"][0]["elements"].get<int>() > 10);
  CHECK(fs::exists(folder / "palm.svg"));

  ok = grow(scenes + "palm.json --edit " + scenes + "palm.edits.json -o " + (folder / "bent.png").string() + " --json",
            folder);
  REQUIRE(ok.status == 0);
  const nlohmann::json edited = nlohmann::json::parse(ok.output);
  CHECK(edited["regrown_guides"].get<int>() < 9);  // trunk1 is pinned and feeds nothing that moved
  CHECK(fs::file_size(folder / "bent.png") > 1000);

  const std::string guide = R"({"id": "A", "polygon": [[0,0],[1,0],[1,1],[0,1]], "lsystem": "w"})";
  write(folder / "unknown_guide.json", R"({"lsystems": {"w": "axiom: F"}, "guides": [)" + guide +
                                           R"(], "links": [{"from": "A", "from_edge": 0, "to": "B", "to_edge": 0}]})");
  write(folder / "crossed.json", R"({"guides": [{"id": "A", "polygon": [[0,0],[1,1],[1,0],[0,1]]}]})");
  write(folder / "no_lsystem.json", R"({"guides": [)" + guide + "]}");
  write(folder / "forever.json", R"({"lsystems": {"w": "axiom: ?seed\n?seed(x, y, h) -> A\nA -> f(0) A"},
    "guides": [{"id": "A", "polygon": [[0,0],[1,0],[1,1],[0,1]], "lsystem": "w", "seeds": [{"position": [0.5, 0.5]}]}],
    "limits": {"max_steps": 100}})");
  const std::pair<const char*, const char*> bad[] = {
      {"unknown_guide.json", "links[0].to: unknown guide 'B'"},
      {"crossed.json", "guide 'A': the polygon intersects itself"},
      {"no_lsystem.json", "guides[0].lsystem: unknown L-system 'w'"},
      {"forever.json", "derivation limit"},
  };
  for (const auto& [file, message] : bad) {
    INFO(file);
    const dg::test::CliRun failed = grow((folder / file).string() + " -o " + (folder / "x.svg").string(), folder);
    CHECK(failed.status == 2);
    CHECK(failed.output.find(file) != std::string::npos);
    CHECK(failed.output.find(message) != std::string::npos);
    CHECK(std::count(failed.output.begin(), failed.output.end(), '\n') == 1);
  }
  CHECK_FALSE(fs::exists(folder / "x.svg"));
}
