// analyze's NAME.sites.ply/.png: dockers filled and docking sites drawn around them in their
// operation's colour, as the report says.

#include "support/cli_run.h"

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

namespace fs = std::filesystem;

namespace {

using Rgb = std::array<std::uint8_t, 3>;

// Vertex colours of a binary PLY as the project writes it (x, y, z doubles, then red, green,
// blue bytes per vertex).
std::set<Rgb> vertex_colors(const fs::path& ply) {
  std::ifstream in(ply, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t count_at = bytes.find("element vertex ");
  const std::size_t header_end = bytes.find("end_header\n");
  REQUIRE(count_at != std::string::npos);
  REQUIRE(header_end != std::string::npos);
  REQUIRE(bytes.find("property uchar red") < header_end);
  const std::size_t vertices = std::stoul(bytes.substr(count_at + 15));
  const std::size_t begin = header_end + 11, stride = 3 * sizeof(double) + 3;
  REQUIRE(bytes.size() >= begin + vertices * stride);
  std::set<Rgb> colors;
  for (std::size_t v = 0; v < vertices; ++v) {
    Rgb c;
    std::memcpy(c.data(), bytes.data() + begin + v * stride + 3 * sizeof(double), 3);
    colors.insert(c);
  }
  return colors;
}

}  // namespace

TEST_CASE("analyze: the docking-site picture shows insert and replace sites of a fence, none for a gear", "[tools][pictures]") {
  const fs::path folder = dg::test::fresh_folder("dockgrammar-site-picture-test");
  // fence_4 has insert, delete and replace sites (paper: a fence's posts and rails are inserted
  // and deleted along the pitch).
  const dg::test::AnalyzedModel fence = dg::test::analyze_model("fence_4", folder / "fence");
  REQUIRE(fence.run.status == 0);
  REQUIRE(fs::exists(folder / "fence" / "fence_4.sites.png"));
  const std::set<Rgb> colors = vertex_colors(folder / "fence" / "fence_4.sites.ply");
  CHECK(colors.count(Rgb{20, 120, 30}) == 1);    // an insert site
  CHECK(colors.count(Rgb{150, 215, 150}) == 1);  // an insert docker
  CHECK(colors.count(Rgb{20, 60, 170}) == 1);    // a replace site
  std::ifstream report(folder / "fence" / "fence_4.report.md");
  const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
  CHECK(text.find("Picture: `fence_4.sites.png`") != std::string::npos);
  // Its context-free rules offer choices, and the report says what generate does with them and
  // how its grid is varied instead.
  CHECK(text.find("With these rules: generate makes random variants from them; generate --rules grid draws the "
                  "counts of grid1 instead, resize sets them.") != std::string::npos);

  // --json lists the pictures written, each on disk.
  const dg::test::CliRun json = dg::test::run_cli("analyze " + std::string(DOCKGRAMMAR_SOURCE_DIR) +
                                                      "/assets/models/fence_4.obj -q --json -o " + (folder / "json").string(),
                                                  folder);
  REQUIRE(json.status == 0);
  const nlohmann::json summary = nlohmann::json::parse(json.output);
  std::set<std::string> listed;
  for (const auto& png : summary.at("pictures")) {
    CHECK(fs::exists(png.get<std::string>()));
    listed.insert(fs::path(png.get<std::string>()).filename().string());
  }
  CHECK(listed == std::set<std::string>{"fence_4.grid1.png", "fence_4.rules.png", "fence_4.sites.png"});
  // What the fence shows but analyze could not use: only docking sites whose site's image also
  // runs where nothing is replaced. Its translation gives its grid, and its posts' and rails'
  // quarter turns close full turns.
  const nlohmann::json& missing = summary.at("missing");
  REQUIRE(missing.is_array());
  REQUIRE(missing.size() == 1);
  CHECK(missing[0].get<std::string>().find("docking sites give no context-free production: part of the site's image borders "
                                           "nothing the operation replaces") != std::string::npos);
  CHECK(text.find("## Not yet built\n\n- ") != std::string::npos);

  // The gear's rotations leave no docking site: no picture, and the report names none.
  const dg::test::AnalyzedModel gear = dg::test::analyze_model("gear_12", folder / "gear");
  REQUIRE(gear.run.status == 0);
  CHECK_FALSE(fs::exists(folder / "gear" / "gear_12.sites.png"));
  std::ifstream gear_report(folder / "gear" / "gear_12.report.md");
  const std::string gear_text((std::istreambuf_iterator<char>(gear_report)), std::istreambuf_iterator<char>());
  CHECK(gear_text.find(".sites.png") == std::string::npos);
  // Its 12 teeth close a full turn, which no grid can extend: nothing is listed as not built.
  CHECK(gear_text.find("Not yet built") == std::string::npos);
  CHECK(gear.run.output.find("not built") == std::string::npos);
}
