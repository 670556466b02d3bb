// `resize` and `generate` write the grammar's materials: OBJ with mtllib/usemtl and its MTL,
// checked face by face against the material fence's ground truth.

#include "geometry/model_io.h"
#include "geometry/png_reader.h"
#include "grammar/grammar_file.h"
#include "support/asset_grammar.h"
#include "support/cli_run.h"
#include "support/corpus.h"
#include "support/material_models.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>

using dg::Vec3;

namespace {

// Reads an OBJ written by dockgrammar (v, f, mtllib, usemtl lines) and checks that every face's
// material is the fence's material at the face's centroid; returns the faces read.
std::size_t check_obj_materials(const std::filesystem::path& path) {
  std::ifstream in(path);
  REQUIRE(in);
  const std::vector<std::string> names = {"wood", "metal", "cap"};
  std::vector<Vec3> positions;
  std::string line, library, material;
  std::size_t faces = 0;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "mtllib") {
      words >> library;
    } else if (keyword == "usemtl") {
      words >> material;
    } else if (keyword == "v") {
      Vec3 p;
      words >> p.x() >> p.y() >> p.z();
      positions.push_back(p);
    } else if (keyword == "f") {
      std::size_t a = 0, b = 0, c = 0;
      words >> a >> b >> c;
      const Vec3 centroid = (positions.at(a - 1) + positions.at(b - 1) + positions.at(c - 1)) / 3.0;
      INFO("face " << faces << " at " << centroid.transpose());
      CHECK(material == names[dg::test::fence_material_at(centroid)]);
      ++faces;
    }
  }
  CHECK(library == path.stem().string() + ".mtl");
  std::ifstream mtl(path.parent_path() / library);
  const std::string text((std::istreambuf_iterator<char>(mtl)), std::istreambuf_iterator<char>());
  CHECK(text.find("newmtl wood\nKd 0.55 0.35 0.2\n") != std::string::npos);
  CHECK(text.find("newmtl metal\nKd 0.5 0.5 0.55\n") != std::string::npos);
  CHECK(text.find("newmtl cap\nKd 0.1 0.1 0.1\n") != std::string::npos);
  return faces;
}

// Pixels of a PNG clearly redder than blue (the fence's wood; grey and white are not).
std::size_t brownish_pixels(const std::filesystem::path& png) {
  std::size_t count = 0;
  for (const dg::Rgba8& p : dg::read_png(png).pixels) count += p.r > p.b + 40 ? 1 : 0;
  return count;
}

}  // namespace

TEST_CASE("materials: resize and generate write OBJ with the exemplar's materials", "[tools][materials]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-material-cli-test");
  const dg::ShapeGrammar grammar = dg::test::model_grammar(dg::test::material_fence(4), false);
  REQUIRE(grammar.grids.size() == 1);
  dg::write_grammar(folder / "fence.grammar.json", grammar);
  const std::string grammar_file = (folder / "fence.grammar.json").string();

  const dg::test::CliRun resize = dg::test::run_cli("resize " + grammar_file + " --grid grid1=6 -q -o " +
                                                        (folder / "wide.obj").string(), folder);
  REQUIRE(resize.status == 0);
  CHECK(check_obj_materials(folder / "wide.obj") > 0);

  const dg::test::CliRun generate =
      dg::test::run_cli("generate " + grammar_file + " --count 2 --seed 3 -q -o " + (folder / "variants").string(), folder);
  REQUIRE(generate.status == 0);
  for (const std::string name : {"variant_00000.obj", "variant_00001.obj"}) {
    INFO(name);
    CHECK(check_obj_materials(folder / "variants" / name) > 0);
  }
}

TEST_CASE("materials: resize pictures show the materials' colours", "[tools][materials]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-material-picture-test");
  dg::ShapeGrammar grammar = dg::test::model_grammar(dg::test::material_fence(4), false);
  dg::write_grammar(folder / "coloured.grammar.json", grammar);
  grammar.materials.clear();
  dg::write_grammar(folder / "plain.grammar.json", grammar);
  for (const std::string name : {"coloured", "plain"}) {
    const dg::test::CliRun run = dg::test::run_cli("resize " + (folder / (name + ".grammar.json")).string() +
                                                       " --grid grid1=5 --picture -q -o " + (folder / (name + ".obj")).string(),
                                                   folder);
    REQUIRE(run.status == 0);
  }
  CHECK(brownish_pixels(folder / "coloured.png") > 1000);
  CHECK(brownish_pixels(folder / "plain.png") == 0);
}

TEST_CASE("materials: analyze and resize an OBJ + MTL with painted windows, read the result back", "[tools][materials]") {
  // The whole way: OBJ + MTL in, grammar, resized OBJ + MTL out, read again by read_model.
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-material-roundtrip-test");
  const dg::Model wall = dg::test::painted_wall(6, 4);
  dg::write_mesh_with_materials(folder / "wall.obj", wall.mesh, wall.materials);
  const dg::test::CliRun analyze = dg::test::run_cli(
      "analyze " + (folder / "wall.obj").string() + " --match-materials -q -o " + (folder / "grammar").string(), folder);
  REQUIRE(analyze.status == 0);
  const std::filesystem::path grammar_file = folder / "grammar" / "wall.grammar.json";
  const dg::ShapeGrammar grammar = dg::read_grammar(grammar_file);
  CHECK(grammar.materials == wall.materials);
  REQUIRE(grammar.grids.size() == 1);
  REQUIRE(grammar.grids[0].rule.directions.size() == 2);
  std::vector<int> counts;
  for (const dg::GridDirection& d : grammar.grids[0].rule.directions) counts.push_back(d.count + 3);
  const dg::test::CliRun resize = dg::test::run_cli(
      "resize " + grammar_file.string() + " --grid grid1=" + std::to_string(counts[0]) + "x" + std::to_string(counts[1]) +
          " -q -o " + (folder / "wide.obj").string(),
      folder);
  REQUIRE(resize.status == 0);

  const dg::Model wide = dg::read_model(folder / "wide.obj");
  REQUIRE(wide.mesh.has_materials());
  REQUIRE(wide.materials.size() == 2);
  double glass = 0.0;
  for (std::size_t t = 0; t < wide.mesh.triangles.size(); ++t) {
    const auto [a, b, c] = wide.mesh.corners(t);
    const dg::Material& material = wide.materials[wide.mesh.materials[t]];
    INFO("triangle " << t << " at " << ((a + b + c) / 3.0).transpose());
    REQUIRE(material == wall.materials[dg::test::painted_wall_material_at((a + b + c) / 3.0)]);
    if (material.name == "glass") glass += 0.5 * wide.mesh.area_vector(t).norm();
  }
  CHECK(glass == Approx(counts[0] * counts[1] * 1.5).epsilon(1e-9));  // one window per unit
}

TEST_CASE("materials: --same-material makes random tints one material for info and analyze", "[tools][materials]") {
  // Wall stripes between glass stripes of two tints in no periodic order: with the tints as one
  // material the stripes repeat every two (3.0), and the report and JSON name the group.
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-same-material-test");
  std::vector<std::uint32_t> stripes;
  for (std::uint32_t tint : {1, 2, 2, 1, 1, 2, 1, 2, 2, 1}) stripes.insert(stripes.end(), {0u, tint});
  const dg::Model wall = dg::test::striped_wall(stripes, {"wall", "glass_green", "glass_blue"});
  dg::write_mesh_with_materials(folder / "stripes.obj", wall.mesh, wall.materials);
  const std::string model = (folder / "stripes.obj").string();

  // Geometry alone finds no grid on a flat wall; with --geometry-only the summary names the tints
  // that swap and the option that gives the grid (measured: material_hint).
  const std::string plain_folder = (folder / "plain").string();
  const dg::test::CliRun geometric = dg::test::run_cli("analyze " + model + " --geometry-only -q -o " + plain_folder, folder);
  REQUIRE(geometric.status == 0);
  CHECK(geometric.output.find("grids: none found") != std::string::npos);
  CHECK(geometric.output.find("hint: the model's repeats are drawn in materials") != std::string::npos);
  CHECK(geometric.output.find("--same-material 'glass_green,glass_blue' gives a 1-grid") != std::string::npos);
  std::ifstream plain_report(folder / "plain" / "stripes.report.md");
  const std::string plain_text((std::istreambuf_iterator<char>(plain_report)), std::istreambuf_iterator<char>());
  CHECK(plain_text.find("`--same-material 'glass_green,glass_blue'` gives a 1-grid") != std::string::npos);
  // The report's stage times follow the pipeline, the hint's search between grids and docking sites.
  auto stages_in_order = [](const std::string& text, const std::vector<std::string>& stages) {
    std::size_t previous = 0;
    for (const std::string& stage : stages) {
      INFO(stage);
      const std::size_t at = text.find(stage);
      REQUIRE(at != std::string::npos);
      CHECK(at > previous);
      previous = at;
    }
  };
  stages_in_order(plain_text, {"- load:", "- voxel surface:", "- symmetry candidates:", "- grid rules:", "- material hint:",
                               "- docking sites:", "- context-free rules:"});
  const dg::test::CliRun geometric_json =
      dg::test::run_cli("analyze " + model + " --geometry-only -q --json -o " + plain_folder, folder);
  const nlohmann::json hint = nlohmann::json::parse(geometric_json.output)["material_hint"];
  CHECK(hint["same_material"] == nlohmann::json::array({nlohmann::json::array({"glass_green", "glass_blue"})}));
  CHECK(hint["grid_counts"].size() == 1);
  CHECK(hint["applied"] == false);
  CHECK(nlohmann::json::parse(geometric_json.output)["grids"].empty());
  CHECK(nlohmann::json::parse(geometric_json.output)["timings_s"].contains("material hint"));

  // By default analyze goes on with the tints grouped, and says so: the grammar holds the grid
  // that --same-material gives.
  const dg::test::CliRun applied = dg::test::run_cli("analyze " + model + " -q -o " + (folder / "applied").string(), folder);
  REQUIRE(applied.status == 0);
  CHECK(applied.output.find("grid grid1: 1-grid") != std::string::npos);
  CHECK(applied.output.find("materials: geometry alone gave no grid; the model's repeats are drawn in materials, some of "
                            "which take one another's place at random (glass_green,glass_blue), so analyze went on as with "
                            "--same-material 'glass_green,glass_blue', which gives a 1-grid") != std::string::npos);
  CHECK(applied.output.find("--geometry-only keeps to geometry") != std::string::npos);
  std::ifstream applied_report(folder / "applied" / "stripes.report.md");
  const std::string applied_text((std::istreambuf_iterator<char>(applied_report)), std::istreambuf_iterator<char>());
  CHECK(applied_text.find("`glass_green`, `glass_blue` count as one") != std::string::npos);
  CHECK(applied_text.find("Materials: geometry alone gave no grid;") != std::string::npos);
  stages_in_order(applied_text, {"- load:", "- symmetry candidates:", "- analysis by geometry alone (no grid):",
                                 "- material hint:", "- grid rules:", "- docking sites:", "- context-free rules:"});
  const dg::ShapeGrammar applied_grammar = dg::read_grammar(folder / "applied" / "stripes.grammar.json");
  const dg::ShapeGrammar plain_grammar = dg::read_grammar(folder / "plain" / "stripes.grammar.json");
  CHECK(plain_grammar.grids.empty());

  const dg::test::CliRun info = dg::test::run_cli("info " + model + " --json --same-material 'glass_*'", folder);
  REQUIRE(info.status == 0);
  const nlohmann::json summary = nlohmann::json::parse(info.output);
  const nlohmann::json tints = nlohmann::json::array({nlohmann::json::array({"glass_green", "glass_blue"})});
  CHECK(summary["match_materials"] == true);
  CHECK(summary["material_groups"] == tints);

  const dg::test::CliRun analyze =
      dg::test::run_cli("analyze " + model + " --json -q --same-material 'glass_*' -o " + (folder / "out").string(), folder);
  REQUIRE(analyze.status == 0);
  const nlohmann::json result = nlohmann::json::parse(analyze.output);
  CHECK(result["material_groups"] == tints);
  REQUIRE(result["grids"].size() == 1);
  bool two_stripes = false;
  for (const nlohmann::json& t : result["grids"][0]["transforms"])
    two_stripes = two_stripes || std::abs(std::abs(t[1][3].get<double>()) - 2 * dg::test::kStripeHeight) < 1e-6;
  CHECK(two_stripes);
  // The grid analyze went on with is the one the option gives.
  REQUIRE(applied_grammar.grids.size() == 1);
  CHECK(dg::exemplar_counts(applied_grammar.grids[0].rule) == result["grids"][0]["counts"].get<std::vector<int>>());
  std::ifstream report(folder / "out" / "stripes.report.md");
  const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
  CHECK(text.find("`glass_green`, `glass_blue` count as one") != std::string::npos);
  CHECK(text.find("Hint: the model's repeats are drawn in materials") == std::string::npos);
  CHECK_FALSE(result["timings_s"].contains("material hint"));  // matched materials: no hint search, no timing

  const dg::test::CliRun unknown = dg::test::run_cli("info " + model + " --same-material 'glas,wall'", folder);
  CHECK(unknown.status == 2);
  CHECK(unknown.output.find("no material matches 'glas' (the model's materials: wall, glass_green, glass_blue)") !=
        std::string::npos);
  // A model without materials has nothing to group.
  const dg::test::CliRun bare = dg::test::run_cli(
      "info " + (std::filesystem::path(DOCKGRAMMAR_SOURCE_DIR) / "assets" / "models" / "fence_4.obj").string() +
          " --same-material glass",
      folder);
  CHECK(bare.status == 2);
  CHECK(bare.output.find("no material matches 'glass' (the model's materials: none)") != std::string::npos);
  std::filesystem::remove_all(folder);
}

TEST_CASE("corpus: analyze gives the Hochhaus Asemwald its 2-grid of floors, its window tints grouped by itself",
          "[tools][materials][corpus]") {
  const auto path = dg::test::corpus_file_if_present("meshes/arch-fg-hochhaus-asemwald/hochhaus_asemwald.obj");
  if (!path) return;
  // Its facades are flat: geometry alone gives no grid, the tints grouped give floors x bays.
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-hochhaus-materials");
  const dg::test::CliRun run = dg::test::run_cli("analyze " + path->string() + " -q --json -o " + folder.string(), folder);
  REQUIRE(run.status == 0);
  const nlohmann::json result = nlohmann::json::parse(run.output);
  REQUIRE(result["grids"].size() == 1);
  CHECK(result["grids"][0]["dims"] == 2);
  std::vector<int> counts = result["grids"][0]["counts"].get<std::vector<int>>();
  std::sort(counts.begin(), counts.end());
  CHECK(counts == std::vector<int>{1, 21});  // as --same-material 'glas*,jalousie*' gives (test_grid_rules.cpp)
  CHECK(result["match_materials"] == true);
  CHECK(result["material_hint"]["applied"] == true);
  CHECK(result["material_groups"] ==
        nlohmann::json::array({nlohmann::json::array({"glas1", "glas2", "glas3", "glas4", "jalousie1", "jalousie2"})}));
  std::filesystem::remove_all(folder);
}
