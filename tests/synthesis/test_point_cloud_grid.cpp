// Grids of point clouds: a scan-like cloud drawn on a generated facade gives the facade's grid,
// and its resized points lie on (and cover) the generator's larger facade. The command-line test
// also runs the context-free rules of points end to end.

#include "synthesis/grid_resize.h"
#include "synthesis/verify.h"

#include "assets/generator/asset.h"
#include "geometry/model_io.h"
#include "geometry/surface_sampling.h"
#include "grammar/docking_sites.h"
#include "grammar/grammar_file.h"
#include "grammar/grid_cut.h"
#include "support/cli_run.h"
#include "support/corpus.h"
#include "support/mesh_distance.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fstream>
#include <iterator>
#include <set>

using dg::Vec3;

namespace {

dg::TriangleMesh facade(int columns, int rows) {
  return dg::assets::make_asset("facade", {{"columns", columns}, {"rows", rows}}).mesh;
}

// Count per direction of `grid` for the facade's columns (along x) and rows (along z).
std::vector<int> facade_counts(const dg::GridRule& grid, int columns, int rows) {
  std::vector<int> counts;
  for (const dg::GridDirection& d : grid.directions) counts.push_back(std::abs(d.direction.x()) > 0.99 ? columns : rows);
  return counts;
}

// Fraction of `samples` with a point of `cloud` in their voxel of size `cell` or a neighbour.
double covered_fraction(const std::vector<Vec3>& samples, const std::vector<Vec3>& cloud, double cell) {
  std::set<std::array<long, 3>> occupied;
  auto voxel = [&](const Vec3& p) {
    return std::array<long, 3>{std::lround(std::floor(p.x() / cell)), std::lround(std::floor(p.y() / cell)),
                               std::lround(std::floor(p.z() / cell))};
  };
  for (const Vec3& p : cloud) occupied.insert(voxel(p));
  std::size_t covered = 0;
  for (const Vec3& s : samples) {
    const auto v = voxel(s);
    bool found = false;
    for (long dx = -1; dx <= 1 && !found; ++dx)
      for (long dy = -1; dy <= 1 && !found; ++dy)
        for (long dz = -1; dz <= 1 && !found; ++dz) found = occupied.count({v[0] + dx, v[1] + dy, v[2] + dz}) > 0;
    covered += found ? 1 : 0;
  }
  return static_cast<double>(covered) / static_cast<double>(samples.size());
}

}  // namespace

TEST_CASE("a point cloud drawn on the facade gives its 2-grid and resized points form the larger facade",
          "[synthesis][grid][cloud]") {
  const dg::TriangleMesh exemplar = facade(3, 4);
  dg::Model model;
  model.cloud.positions = dg::sample_surface(exemplar, 400000, 1).positions;  // no normals: scan-like
  const dg::PreparedModel prepared = dg::prepare_model(std::move(model));
  const double eps = prepared.surface.eps();
  const dg::SymmetryResult symmetries = dg::detect_symmetries(prepared);
  const std::vector<dg::GridRule> grids = dg::find_grids(prepared, symmetries);
  REQUIRE(grids.size() == 1);
  const dg::GridRule& grid = grids[0];
  REQUIRE(grid.directions.size() == 2);
  // The generator's counts and pitches (3 columns, 4 rows, 3 m apart), as the mesh gives them.
  CHECK(grid.directions[0].count == facade_counts(grid, 3, 4)[0]);
  CHECK(grid.directions[1].count == facade_counts(grid, 3, 4)[1]);
  for (const dg::GridDirection& d : grid.directions) CHECK(d.pitch == Approx(3.0).margin(0.01 * eps));

  const std::vector<dg::GridPiece> pieces = dg::cut_grid_points(prepared.model.cloud, grid);
  std::size_t stored = 0;
  for (const dg::GridPiece& piece : pieces) {
    CHECK(piece.mesh.triangles.empty());
    CHECK(!piece.points.positions.empty());
    stored += piece.points.positions.size();
  }
  // Copies of the repeated unit are not stored: the pieces hold fewer points than the cloud.
  CHECK(stored < prepared.model.cloud.positions.size());

  const std::vector<Vec3> truth_samples = dg::sample_surface(facade(5, 7), 20000, 2).positions;
  for (const auto& [columns, rows] : {std::pair{3, 4}, std::pair{5, 7}}) {
    INFO(columns << " x " << rows);
    const dg::PointCloud resized = dg::resize_grid_points(grid, pieces, facade_counts(grid, columns, rows));
    const dg::TriangleMesh truth = facade(columns, rows);
    // Every point on the generator's facade of that size, and that facade covered by points.
    dg::TriangleMesh points_only;
    points_only.positions = resized.positions;
    CHECK(dg::test::one_sided_distance(points_only, truth) < 0.1 * eps);
    const std::vector<Vec3> samples = dg::sample_surface(truth, 20000, 2).positions;
    CHECK(covered_fraction(samples, resized.positions, eps) > 0.999);
  }
  // The larger facade is r-similar to the scan, checked on the points alone (normals fitted to both).
  dg::Model larger;
  larger.cloud = dg::resize_grid_points(grid, pieces, facade_counts(grid, 5, 7));
  dg::VerifyOptions quick;
  quick.similarity.samples = 300;
  const dg::VerifyReport report = dg::verify_models(prepared.model, std::move(larger), quick);
  CHECK(report.pass);
  CHECK(report.candidate.normals_estimated);
  // The exemplar-sized result is not a cover of the larger facade (the check can fail).
  const dg::PointCloud small = dg::resize_grid_points(grid, pieces, facade_counts(grid, 3, 4));
  CHECK(covered_fraction(truth_samples, small.positions, eps) < 0.8);
}

TEST_CASE("analyze measures a scan's noise and suggests the r that lowers it to 0.1 eps", "[tools][cloud]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-noisy-cloud-test");
  const std::filesystem::path cloud = folder / "noisy_facade.ply";
  dg::PointCloud points = dg::sample_surface(facade(3, 4), 400000, 1);
  points.normals.clear();
  dg::add_noise(points, 0.01, 2);  // eps is 0.0667 at the default r of 0.267: 0.15 eps
  dg::write_point_cloud(cloud, points);
  const dg::test::CliRun analyzed = dg::test::run_cli("analyze " + cloud.string() + " -q --json -o " + (folder / "out").string(), folder);
  REQUIRE(analyzed.status == 0);
  const nlohmann::json summary = nlohmann::json::parse(analyzed.output.substr(analyzed.output.find('{')));
  CHECK(summary["point_cloud"]["noise_eps"].get<double>() == Approx(0.15).epsilon(0.1));
  // `info` gives the same scatter in model units, and within 4 eps about the same (scan noise).
  const dg::test::CliRun info = dg::test::run_cli("info " + cloud.string() + " --json", folder);
  REQUIRE(info.status == 0);
  const nlohmann::json sampling = nlohmann::json::parse(info.output.substr(info.output.find('{')))["cloud_sampling"];
  CHECK(sampling["noise"].get<double>() == Approx(0.01).epsilon(0.1));
  CHECK(sampling["noise_wide"].get<double>() == Approx(0.01).epsilon(0.15));
  CHECK(sampling["spacing"].get<double>() > 0.0);
  // The report suggests 0.267 x 0.15 / 0.10: the r at which test_symmetry_detection.cpp finds
  // this scan's grid.
  std::ifstream report(folder / "out" / "noisy_facade.report.md");
  const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
  CHECK(text.find("noisy:") != std::string::npos);
  CHECK(text.find("-r 0.4") != std::string::npos);
}

TEST_CASE("corpus: analyze calls the building scan's scatter surface detail and suggests no r for it", "[tools][cloud][corpus]") {
  const auto scan = dg::test::corpus_file_if_present("meshes/pointcloud-cgal-building/building.ply");
  if (!scan) return;
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-rough-cloud-test");
  const dg::test::CliRun analyzed = dg::test::run_cli("analyze " + scan->string() + " -q --json -o " + folder.string(), folder);
  REQUIRE(analyzed.status == 0);
  const nlohmann::json summary = nlohmann::json::parse(analyzed.output.substr(analyzed.output.find('{')));
  // 0.22 eps within 2 eps, 0.48 within 4 eps: no scan noise that a larger r would shrink.
  CHECK(summary["point_cloud"]["noise_eps"].get<double>() > 0.15);
  std::ifstream report(folder / "building.report.md");
  const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
  CHECK(text.find("rough:") != std::string::npos);
  CHECK(text.find("noisy:") == std::string::npos);
}

TEST_CASE("docking sites of a point cloud come from its symmetries", "[grammar][cloud]") {
  dg::Model model;
  model.cloud.positions = dg::sample_surface(facade(2, 3), 400000, 3).positions;
  const dg::PreparedModel prepared = dg::prepare_model(std::move(model));
  const dg::SymmetryResult symmetries = dg::detect_symmetries(prepared);
  REQUIRE(!symmetries.symmetries.empty());
  const dg::DockingSiteResult docking = dg::find_docking_sites(prepared, symmetries);
  CHECK(docking.stats.motions > 0);
  CHECK(!docking.sites.empty());
  for (const dg::DockingSite& site : docking.sites) {
    CHECK(!site.docker.empty());
    CHECK(!site.site.empty());
  }
}

TEST_CASE("analyze symmetry resize and generate on a point-cloud file", "[tools][cloud]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-point-cloud-test");
  const std::filesystem::path cloud = folder / "facade_points.ply";
  dg::write_point_cloud(cloud, dg::sample_surface(facade(2, 3), 400000, 3));
  const dg::test::CliRun analyzed = dg::test::run_cli("analyze " + cloud.string() + " -q --json -o " + (folder / "out").string(), folder);
  REQUIRE(analyzed.status == 0);
  const nlohmann::json summary = nlohmann::json::parse(analyzed.output.substr(analyzed.output.find('{')));
  REQUIRE(summary["grids"].size() == 1);
  CHECK(summary["grids"][0]["dims"] == 2);
  CHECK(summary["grids"][0]["pieces"][0].contains("points"));
  CHECK(!summary["productions"].empty());  // context-free rules of points (test_point_cloud_rules.cpp)
  CHECK(summary["dockers"].get<int>() > 0);
  CHECK(summary["point_cloud"]["points"] == 400000);
  CHECK(summary["point_cloud"]["points_per_voxel"].get<double>() > 3.0);
  CHECK(summary["point_cloud"]["noise_eps"].get<double>() < 0.01);  // sampled exactly on the surface
  {
    std::ifstream report(folder / "out" / "facade_points.report.md");
    const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
    CHECK(text.find("eps off the surface (rms)") != std::string::npos);
    CHECK(text.find("noisy:") == std::string::npos);
    CHECK(text.find("rough:") == std::string::npos);
  }
  const std::filesystem::path grammar_path = folder / "out" / "facade_points.grammar.json";
  std::ifstream grammar_file(grammar_path);
  const nlohmann::json grammar_json = nlohmann::json::parse(grammar_file);
  CHECK(grammar_json["surface"] == "points");
  CHECK(grammar_json["version"] == dg::kGrammarFileVersion);
  const dg::ShapeGrammar grammar = dg::read_grammar(grammar_path);
  CHECK(dg::is_point_grammar(grammar));
  CHECK(grammar.exemplar_points.positions.size() == 400000);
  CHECK(grammar.context_free.of_points());
  for (const std::string picture : {"facade_points.grid1.png", "facade_points.sites.png", "facade_points.rules.png"})
    CHECK(std::filesystem::exists(folder / "out" / picture));
  nlohmann::json unknown_surface = grammar_json;
  unknown_surface["surface"] = "voxels";
  std::ofstream(folder / "out" / "unknown.grammar.json") << unknown_surface.dump();
  CHECK_THROWS_WITH(dg::read_grammar(folder / "out" / "unknown.grammar.json"), Catch::Contains("\"surface\" must be"));

  // Symmetry pictures colour the points by their cells.
  const dg::test::CliRun pictured =
      dg::test::run_cli("symmetry " + cloud.string() + " -q --top 1 -o " + (folder / "symmetry").string(), folder);
  CHECK(pictured.status == 0);
  CHECK(std::filesystem::exists(folder / "symmetry" / "symmetry_01.png"));
  CHECK(dg::read_model(folder / "symmetry" / "symmetry_01.ply").cloud.positions.size() == 400000);

  // Resize: counts + 1 in each direction give a point cloud with more points.
  const std::vector<int> counts = summary["grids"][0]["counts"].get<std::vector<int>>();
  const std::string grid = "grid1=" + std::to_string(counts[0] + 1) + "x" + std::to_string(counts[1] + 1);
  const dg::test::CliRun resized = dg::test::run_cli(
      "resize " + grammar_path.string() + " -q --picture --grid " + grid + " -o " + (folder / "bigger.ply").string(), folder);
  REQUIRE(resized.status == 0);
  const dg::Model bigger = dg::read_model(folder / "bigger.ply");
  CHECK(bigger.is_point_cloud());
  CHECK(bigger.cloud.positions.size() > grammar.exemplar_points.positions.size());
  CHECK(std::filesystem::exists(folder / "bigger.png"));
  // The resized cloud and a generated variant are r-similar to the scan they came from.
  auto verified = [&](const std::filesystem::path& candidate) {
    const dg::test::CliRun run =
        dg::test::run_cli("verify " + cloud.string() + " " + candidate.string() + " -q --json --samples 300", folder);
    CHECK(run.status == 0);
    return nlohmann::json::parse(run.output.substr(run.output.find('{')));
  };
  const nlohmann::json bigger_checked = verified(folder / "bigger.ply");
  CHECK(bigger_checked["point_cloud"] == true);
  CHECK(bigger_checked["points"].get<std::size_t>() == bigger.cloud.positions.size());
  CHECK(bigger_checked["r_similar_fraction"].get<double>() >= 0.995);
  CHECK_FALSE(bigger_checked.contains("closed"));
  dg::write_mesh(folder / "facade.obj", facade(2, 3));
  const dg::test::CliRun mixed =
      dg::test::run_cli("verify " + cloud.string() + " " + (folder / "facade.obj").string() + " -q", folder);
  CHECK(mixed.status == 2);
  CHECK(mixed.output.find("two meshes or two point clouds") != std::string::npos);
  const dg::test::CliRun as_obj =
      dg::test::run_cli("resize " + grammar_path.string() + " -q --grid " + grid + " -o " + (folder / "bigger.obj").string(), folder);
  CHECK(as_obj.status == 2);
  CHECK(as_obj.output.find("point clouds are written as .ply only") != std::string::npos);

  // Generate: point clouds by default (context-free variants, then grid variants when asked), the
  // same seed the same files, an OBJ request refused.
  for (const std::string rules : {"context-free", "grid"}) {
    const std::filesystem::path variants = folder / ("variants-" + rules);
    const dg::test::CliRun generated = dg::test::run_cli(
        "generate " + grammar_path.string() + " -q --count 2 --rules " + rules + " -o " + variants.string(), folder);
    REQUIRE(generated.status == 0);
    CHECK(dg::read_model(variants / "variant_00000.ply").is_point_cloud());
    std::ifstream manifest_file(variants / "manifest.json");
    const nlohmann::json manifest = nlohmann::json::parse(manifest_file);
    CHECK(manifest["variants"][1]["rules"] == rules);
    if (rules == "grid") CHECK(manifest["variants"][1]["changed"] == true);  // upright, this cloud's alternatives look alike
    CHECK(manifest["variants"][1]["points"].get<std::size_t>() > 0);
    CHECK(verified(variants / "variant_00001.ply")["pass"] == true);
  }
  const dg::test::CliRun again = dg::test::run_cli(
      "generate " + grammar_path.string() + " -q --count 2 --rules context-free -o " + (folder / "again").string(), folder);
  REQUIRE(again.status == 0);
  auto bytes = [](const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  CHECK(bytes(folder / "again" / "variant_00001.ply") == bytes(folder / "variants-context-free" / "variant_00001.ply"));
  const dg::test::CliRun obj_variants = dg::test::run_cli(
      "generate " + grammar_path.string() + " -q --count 1 --format obj -o " + (folder / "obj").string(), folder);
  CHECK(obj_variants.status == 2);
  CHECK(obj_variants.output.find("use --format ply") != std::string::npos);
  std::filesystem::remove_all(folder);
}
