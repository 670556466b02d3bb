// analyze's report on grids: when none is found it names the repeating translation a reader most
// likely expected one from, and why its units could not be cut apart; a further run of a grid's
// motion says which grid's it is.

#include "assets/generator/asset.h"
#include "geometry/model_io.h"
#include "support/cli_run.h"
#include "support/shapes.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace {

// Writes `mesh` as NAME.obj in a fresh folder, runs `analyze` on it and returns NAME.report.md.
std::string analyze_report(const dg::TriangleMesh& mesh, const std::string& name) {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-grid-report-" + name);
  const std::filesystem::path model = folder / (name + ".obj");
  dg::write_mesh(model, mesh);
  const dg::test::CliRun run = dg::test::run_cli("analyze " + model.string() + " -q -o " + folder.string(), folder);
  INFO(run.output);
  REQUIRE(run.status == 0);
  std::ifstream in(folder / (name + ".report.md"));
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

TEST_CASE("analyze: with no grid, the report names the strongest repeating translation and why it gave none",
          "[tools][grids]") {
  // Two equal boxes, 2 apart, above a sphere: the translation maps one box onto the other, but
  // every plane between them crosses the sphere, which does not repeat.
  dg::TriangleMesh mesh = dg::test::make_sphere(dg::Vec3(0.0, 0.0, -2.0), 2.5, 24, 48);
  dg::test::append(mesh, dg::test::make_box(dg::Vec3(-1.5, -0.5, 1.0), dg::Vec3(-0.5, 0.5, 2.0)));
  dg::test::append(mesh, dg::test::make_box(dg::Vec3(0.5, -0.5, 1.0), dg::Vec3(1.5, 0.5, 2.0)));
  const std::string report = analyze_report(mesh, "boxes");
  INFO(report);
  CHECK(report.find("No grid found") != std::string::npos);
  const std::size_t named = report.find("The repeating translation with the most r-symmetric area is");
  REQUIRE(named != std::string::npos);
  const std::string sentence = report.substr(named, report.find('\n', named) - named);
  CHECK(sentence.find("|t| = 2;") != std::string::npos);
  CHECK(sentence.find("does not repeat with them") != std::string::npos);
}

TEST_CASE("analyze: with no grid, the report's grid section names the translations that repeat without one",
          "[tools][grids]") {
  // Four equal boxes in a row, 2 apart, on a sphere: the translation repeats, but every plane
  // between two boxes crosses the sphere, so no slab repeats.
  dg::TriangleMesh mesh = dg::test::make_sphere(dg::Vec3(0.0, 0.0, -3.0), 4.0, 32, 64);
  for (int i = 0; i < 4; ++i) {
    const double x = -3.5 + 2.0 * i;
    dg::test::append(mesh, dg::test::make_box(dg::Vec3(x, -0.5, 1.5), dg::Vec3(x + 1.0, 0.5, 2.5)));
  }
  const std::string report = analyze_report(mesh, "row");
  INFO(report);
  const std::size_t grids = report.find("## Grid rules");
  REQUIRE(grids != std::string::npos);
  const std::string section = report.substr(grids, report.find("\n## ", grids + 1) - grids);
  const std::size_t named = section.find("No grid found. Repeating, but without a grid: translation F");
  REQUIRE(named != std::string::npos);
  CHECK(section.find("repeats of |t| = 2)", named) != std::string::npos);
  CHECK(report.find("## Not yet built") != std::string::npos);
}

TEST_CASE("analyze: a further run of a grid's motion says so, with where both runs' planes lie", "[tools][grids]") {
  // fence(3), a gate, then 4 more inner posts (pitch 2): the second stretch starts at x = 11.
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-grid-report-gated");
  dg::write_mesh(folder / "gated.obj", dg::assets::make_asset("fence", {{"n", 3}, {"after_gate", 4}}).mesh);
  const dg::test::CliRun run =
      dg::test::run_cli("analyze " + (folder / "gated.obj").string() + " -q --json -o " + folder.string(), folder);
  REQUIRE(run.status == 0);
  std::ifstream in(folder / "gated.report.md");
  const std::string report((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  INFO(report);
  const std::size_t grid2 = report.find("### grid2 (1-grid");
  REQUIRE(grid2 != std::string::npos);
  CHECK(report.find("A further run along the motion of grid1's direction 1: its planes lie from", grid2) ==
        report.find('\n', grid2) + 2);
  CHECK(report.find("A further run") == report.rfind("A further run"));  // grid1 is the first run
  // --json names it too.
  const nlohmann::json grids = nlohmann::json::parse(run.output)["grids"];
  REQUIRE(grids.size() == 2);
  CHECK(grids[0]["further_run_of"].is_null());
  CHECK(grids[1]["further_run_of"] == nlohmann::json({{"grid", "grid1"}, {"direction", 1}}));
}

TEST_CASE("analyze: a grid of bays says whose units it groups, in the summary, the report and --json", "[tools][grids]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-grid-report-bays");
  dg::write_mesh(folder / "bays.obj", dg::test::pilaster_facade(9, 2));
  const dg::test::CliRun text = dg::test::run_cli("analyze " + (folder / "bays.obj").string() + " -q -o " + folder.string(), folder);
  INFO(text.output);
  REQUIRE(text.status == 0);
  CHECK(text.output.find("grid grid2: 2-grid, counts 3x2 (resize with --grid grid2=3x2)\n  it groups the units of grid1's "
                         "direction 1 by 3: grid1 keeps") != std::string::npos);
  std::ifstream in(folder / "bays.report.md");
  const std::string report((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(report.find("### grid2 (2-grid, counts 3x2)\n\nIt groups the units of grid1's direction 1 by 3") != std::string::npos);
  const dg::test::CliRun json =
      dg::test::run_cli("analyze " + (folder / "bays.obj").string() + " -q --json -o " + folder.string(), folder);
  REQUIRE(json.status == 0);
  const nlohmann::json grids = nlohmann::json::parse(json.output)["grids"];
  REQUIRE(grids.size() == 2);
  CHECK(grids[0]["groups_units_of"].is_null());
  CHECK(grids[1]["groups_units_of"] == nlohmann::json({{"grid", "grid1"}, {"direction", 1}, {"factor", 3}}));
}

TEST_CASE("analyze: a grid over a short stretch of a translation's repeats is named as not built for the rest",
          "[tools][grids]") {
  // 16 posts 2 apart standing on one bar, whose top rises as a ramp under the first 10 (x = 3 ..
  // 20), all reaching z = 4: the posts' translation repeats 15 times (their upper parts), but
  // only the slabs beyond the ramp repeat whole.
  const std::vector<std::pair<double, double>> profile{{-1, -1}, {32, -1}, {32, 0}, {20, 0}, {20, 1}, {3, 0}, {-1, 0}};  // x, z
  dg::TriangleMesh mesh;
  for (const double y : {-0.5, 1.0})
    for (const auto& [x, z] : profile) mesh.positions.emplace_back(x, y, z);
  const auto n = static_cast<std::uint32_t>(profile.size());
  for (const dg::Triangle& t : std::vector<dg::Triangle>{{0, 1, 2}, {0, 2, 3}, {0, 3, 5}, {0, 5, 6}, {5, 3, 4}}) {
    mesh.triangles.push_back({t[0], t[2], t[1]});              // the end facing -y
    mesh.triangles.push_back({n + t[0], n + t[1], n + t[2]});  // the end facing +y
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    mesh.triangles.push_back({i, j, n + j});
    mesh.triangles.push_back({i, n + j, n + i});
  }
  auto bar_top = [](double x) { return x > 3 && x < 20 ? (x - 3) / 17 : 0.0; };
  for (int i = 0; i < 16; ++i)
    dg::test::append(mesh, dg::test::make_box(dg::Vec3(2.0 * i, 0.0, bar_top(2.0 * i + 0.25)), dg::Vec3(2.0 * i + 0.5, 0.5, 4.0)));
  const std::string report = analyze_report(mesh, "ramp");
  INFO(report);
  CHECK(report.find("### grid1 (1-grid, counts 6)") != std::string::npos);
  const std::size_t named = report.find("(15 repeats of |t| = 2): the grids along it span only 6 of its repeats");
  REQUIRE(named != std::string::npos);
  CHECK(report.find("## Not yet built") < named);
}
