#include "synthesis/grid_resize.h"

#include "assets/generator/asset.h"
#include "geometry/cleaning.h"
#include "geometry/errors.h"
#include "geometry/topology.h"
#include "grammar/grammar_file.h"
#include "grammar/grid_cut.h"
#include "support/cli_run.h"
#include "support/mesh_distance.h"
#include "support/shapes.h"
#include "synthesis/variants.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <iterator>

using dg::Vec3;

namespace {

struct Grammar {
  double eps = 0.0;
  dg::GridRule grid;
  std::vector<dg::GridPiece> pieces;
};

Grammar grammar_of(const dg::TriangleMesh& mesh) {
  dg::Model model;
  model.mesh = mesh;
  const dg::PreparedModel prepared = dg::prepare_model(std::move(model));
  const dg::SymmetryResult symmetries = dg::detect_symmetries(prepared);
  const std::vector<dg::GridRule> grids = dg::find_grids(prepared, symmetries);
  REQUIRE(grids.size() == 1);
  Grammar g{prepared.surface.eps(), grids[0], dg::cut_grid_pieces(prepared.model.mesh, grids[0], prepared.surface.eps())};
  return g;
}

Grammar grammar_of(const std::string& name, const nlohmann::json& params) {
  return grammar_of(dg::assets::make_asset(name, params).mesh);
}

// The generator's facade(columns, rows) (x from -0.3 to 3 columns + 2.3) with two boxes of
// different sizes on its roof, over x in [4.2, 7.5] and [13.5, 16.5] + `shift`.
dg::TriangleMesh facade_with_rooftop_boxes(int columns, int rows, double shift) {
  dg::TriangleMesh mesh = dg::assets::make_asset("facade", {{"columns", columns}, {"rows", rows}}).mesh;
  const dg::BoundingBox bounds = mesh.bounds();
  const double top = bounds.max.z(), front = bounds.min.y() + 0.1, back = bounds.max.y() - 0.1;
  dg::test::append(mesh, dg::test::make_box(Vec3(4.2, front, top), Vec3(7.5, back, top + 1.5)));
  dg::test::append(mesh, dg::test::make_box(Vec3(13.5 + shift, front, top), Vec3(16.5 + shift, back, top + 2.0)));
  return mesh;
}

std::vector<int> counts_for(const dg::GridRule& grid, const std::vector<std::pair<Vec3, int>>& wanted) {
  std::vector<int> counts;
  for (const auto& d : grid.directions)
    for (const auto& [t, n] : wanted)
      if ((d.translation - t).norm() < 1e-6 || (d.translation + t).norm() < 1e-6) counts.push_back(n);
  REQUIRE(counts.size() == grid.directions.size());
  return counts;
}

void check_same_shape(const dg::TriangleMesh& result, const dg::TriangleMesh& expected, double eps) {
  CHECK(dg::is_closed_and_oriented(result));
  CHECK(dg::test::hausdorff_distance(result, expected) < eps);
  CHECK(result.area() == Approx(expected.area()).epsilon(1e-3));
}

}  // namespace

TEST_CASE("resize fence(4) by five units gives the generator's fence(9)", "[synthesis][grid]") {
  const Grammar g = grammar_of("fence", {{"n", 4}});
  const auto counts = counts_for(g.grid, {{Vec3(2, 0, 0), 9}});
  const dg::TriangleMesh resized = dg::resize_grid(g.grid, g.pieces, counts, g.eps);
  check_same_shape(resized, dg::assets::make_asset("fence", {{"n", 9}}).mesh, g.eps);
  // The exemplar's own counts reproduce it.
  const auto own = counts_for(g.grid, {{Vec3(2, 0, 0), 4}});
  check_same_shape(dg::resize_grid(g.grid, g.pieces, own, g.eps), dg::assets::make_asset("fence", {{"n", 4}}).mesh, g.eps);
}

TEST_CASE("resize facade(3 x 4) to 5 x 7 gives the generator's facade(5, 7)", "[synthesis][grid]") {
  const Grammar g = grammar_of("facade", {{"columns", 3}, {"rows", 4}});
  const auto counts = counts_for(g.grid, {{Vec3(3, 0, 0), 5}, {Vec3(0, 0, 3), 7}});
  const dg::TriangleMesh resized = dg::resize_grid(g.grid, g.pieces, counts, g.eps);
  check_same_shape(resized, dg::assets::make_asset("facade", {{"columns", 5}, {"rows", 7}}).mesh, g.eps);
}

TEST_CASE("facade(5 x 4) with rooftop boxes: one column unit between them, and resizing adds columns there",
          "[synthesis][grid]") {
  // A plane across the whole model meets a box, or the image of one under the motion, at every
  // position but two gaps narrower than the column pitch (3), around x = 0.5 and x = 9, and for
  // two to four columns (6, 9, 12) no two planes a pitch apart are free either. The columns
  // repeat (their powers are symmetries), so they join the rows' grid with one unit, in the
  // wider gap between the boxes.
  const dg::TriangleMesh exemplar = facade_with_rooftop_boxes(5, 4, 0.0);
  const Grammar g = grammar_of(exemplar);
  REQUIRE(g.grid.directions.size() == 2);
  const auto own = counts_for(g.grid, {{Vec3(3, 0, 0), 1}, {Vec3(0, 0, 3), 4}});
  for (std::size_t i = 0; i < own.size(); ++i) CHECK(g.grid.directions[i].count == own[i]);
  const dg::GridDirection& columns = g.grid.directions[own[0] == 1 ? 0 : 1];
  const double first_x = columns.cut * columns.direction.x();
  const double second_x = (columns.cut + columns.pitch) * columns.direction.x();
  CHECK(std::min(first_x, second_x) > 7.5);
  CHECK(std::max(first_x, second_x) < 13.5);
  check_same_shape(dg::resize_grid(g.grid, g.pieces, own, g.eps), exemplar, g.eps);
  // Three columns and six rows: the generator's facade with the first box where it stood and
  // the second two columns further on (both on a roof two rows higher).
  const auto larger = counts_for(g.grid, {{Vec3(3, 0, 0), 3}, {Vec3(0, 0, 3), 6}});
  check_same_shape(dg::resize_grid(g.grid, g.pieces, larger, g.eps), facade_with_rooftop_boxes(7, 6, 6.0), g.eps);
}

// A screw grid (spiral stairs): every added unit is the screw motion applied once more.
TEST_CASE("messy facade: damaged rows stay in the head, so added rows are clean copies", "[synthesis][grid]") {
  // The generator's damage (assets/generator/messy_facade.cpp: doubled faces, a non-manifold
  // fin, slivers, spread by triangle index) makes the two lowest window rows differ from the
  // rows above: they are kept once in the head and a clean row is the repeated unit. The clean
  // facade keeps no unit in a head or tail.
  const Grammar messy = grammar_of("messy_facade", {{"columns", 3}, {"rows", 4}});
  const Grammar clean = grammar_of("facade", {{"columns", 3}, {"rows", 4}});
  for (const dg::GridDirection& d : clean.grid.directions) CHECK(dg::min_units(d) == 0);
  const auto own = counts_for(messy.grid, {{Vec3(3, 0, 0), 3}, {Vec3(0, 0, 3), 4}});
  const auto taller = counts_for(messy.grid, {{Vec3(3, 0, 0), 3}, {Vec3(0, 0, 3), 7}});
  dg::TriangleMesh exemplar_copy = dg::resize_grid(messy.grid, messy.pieces, own, messy.eps);
  dg::TriangleMesh taller_copy = dg::resize_grid(messy.grid, messy.pieces, taller, messy.eps);
  const dg::CleaningReport own_damage = dg::clean_mesh(exemplar_copy);
  const dg::CleaningReport taller_damage = dg::clean_mesh(taller_copy);
  // Three more rows, and not one more doubled face or non-manifold edge.
  CHECK(own_damage.duplicate_triangles > 0);
  CHECK(taller_damage.duplicate_triangles == own_damage.duplicate_triangles);
  CHECK(taller_damage.non_manifold_edges == own_damage.non_manifold_edges);
  CHECK(taller_copy.bounds().size().z() == Approx(exemplar_copy.bounds().size().z() + 9.0).margin(1e-6));
  // The rows cannot shrink below the two kept rows.
  const auto too_low = counts_for(messy.grid, {{Vec3(3, 0, 0), 3}, {Vec3(0, 0, 3), 1}});
  CHECK_THROWS_AS(dg::resize_grid(messy.grid, messy.pieces, too_low, messy.eps), dg::InputError);

  // The kept units survive the grammar file.
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-kept-units-test");
  dg::ShapeGrammar grammar;
  grammar.source_name = "messy_facade_3x4.obj";
  grammar.source_hash = "0";
  grammar.r = 4 * messy.eps;
  grammar.eps = messy.eps;
  grammar.exemplar = exemplar_copy;
  grammar.grids.push_back({messy.grid, messy.pieces});
  dg::write_grammar(folder / "messy.grammar.json", grammar);
  const dg::ShapeGrammar read = dg::read_grammar(folder / "messy.grammar.json");
  REQUIRE(read.grids.size() == 1);
  for (std::size_t i = 0; i < messy.grid.directions.size(); ++i) {
    CHECK(read.grids[0].rule.directions[i].head_units == messy.grid.directions[i].head_units);
    CHECK(read.grids[0].rule.directions[i].tail_units == messy.grid.directions[i].tail_units);
  }
  std::filesystem::remove_all(folder);
}

TEST_CASE("resize spiral stairs(12) to 16 steps gives the generator's stairs(16)", "[synthesis][grid]") {
  const Grammar g = grammar_of("spiral_stairs", {{"steps", 12}});
  REQUIRE(g.grid.directions.size() == 1);
  REQUIRE(g.grid.directions[0].count == 12);
  check_same_shape(dg::resize_grid(g.grid, g.pieces, {12}, g.eps), dg::assets::make_asset("spiral_stairs", {{"steps", 12}}).mesh,
                   g.eps);
  check_same_shape(dg::resize_grid(g.grid, g.pieces, {16}, g.eps), dg::assets::make_asset("spiral_stairs", {{"steps", 16}}).mesh,
                   g.eps);
  check_same_shape(dg::resize_grid(g.grid, g.pieces, {7}, g.eps), dg::assets::make_asset("spiral_stairs", {{"steps", 7}}).mesh,
                   g.eps);
}

TEST_CASE("a screw grid survives the grammar file", "[synthesis][grid]") {
  const Grammar g = grammar_of("spiral_stairs", {{"steps", 12}});
  REQUIRE(g.grid.directions.size() == 1);
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-screw-grid");
  dg::ShapeGrammar file;
  file.source_name = "spiral_stairs_12";
  file.r = 4 * g.eps;
  file.eps = g.eps;
  file.exemplar = dg::assets::make_asset("spiral_stairs", {{"steps", 12}}).mesh;
  file.grids.push_back({g.grid, g.pieces});
  dg::write_grammar(folder / "stairs.grammar.json", file);
  const dg::ShapeGrammar read = dg::read_grammar(folder / "stairs.grammar.json");
  REQUIRE(read.grids.size() == 1);
  const dg::GridDirection& d = read.grids[0].rule.directions[0];
  CHECK(d.motion.rotation.isApprox(g.grid.directions[0].motion.rotation, 1e-9));
  CHECK(d.motion.translation.isApprox(g.grid.directions[0].motion.translation, 1e-9));
  check_same_shape(dg::resize_grid(read.grids[0].rule, read.grids[0].pieces, {14}, g.eps),
                   dg::assets::make_asset("spiral_stairs", {{"steps", 14}}).mesh, g.eps);
  std::filesystem::remove_all(folder);
}

TEST_CASE("resize rejects counts out of range and a wrong number of counts", "[synthesis][grid]") {
  const Grammar g = grammar_of("fence", {{"n", 4}});
  CHECK_THROWS_AS(dg::resize_grid(g.grid, g.pieces, {-1}, g.eps), dg::InputError);
  CHECK_THROWS_AS(dg::resize_grid(g.grid, g.pieces, {g.grid.max_count + 1}, g.eps), dg::InputError);
  CHECK_THROWS_AS(dg::resize_grid(g.grid, g.pieces, {3, 3}, g.eps), dg::InputError);
}

TEST_CASE("grammar file round trip and bad grammar files", "[synthesis][grid]") {
  const Grammar g = grammar_of("fence", {{"n", 4}});
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-grammar-test");
  dg::ShapeGrammar grammar;
  grammar.source_name = "fence_4.obj";
  grammar.source_hash = "0";
  grammar.r = 4 * g.eps;
  grammar.eps = g.eps;
  grammar.exemplar = dg::assets::make_asset("fence", {{"n", 4}}).mesh;
  grammar.grids.push_back({g.grid, g.pieces});
  const auto path = folder / "fence.grammar.json";
  dg::write_grammar(path, grammar);
  const dg::ShapeGrammar read = dg::read_grammar(path);
  REQUIRE(read.grids.size() == 1);
  CHECK(read.grids[0].rule.directions[0].count == 4);
  CHECK(read.grids[0].pieces.size() == g.pieces.size());
  const dg::TriangleMesh resized = dg::resize_grid(read.grids[0].rule, read.grids[0].pieces, {9}, g.eps);
  CHECK(dg::is_closed_and_oriented(resized));

  // Truncated file, wrong version, missing sidecar: InputError naming the file.
  auto write_text = [](const std::filesystem::path& p, const std::string& text) { std::ofstream(p) << text; };
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  write_text(folder / "truncated.grammar.json", text.substr(0, text.size() / 2));
  std::string wrong_version = text;
  const std::string version_field = "\"version\": " + std::to_string(dg::kGrammarFileVersion);
  wrong_version.replace(wrong_version.find(version_field), version_field.size(), "\"version\": 99");
  write_text(folder / "version.grammar.json", wrong_version);
  for (const char* bad : {"truncated.grammar.json", "version.grammar.json"}) {
    try {
      dg::read_grammar(folder / bad);
      FAIL("no error for " << bad);
    } catch (const dg::InputError& e) {
      CHECK(std::string(e.what()).find(bad) != std::string::npos);
    }
  }
  std::filesystem::remove(folder / "fence.grammar.pieces" / "exemplar.ply");
  CHECK_THROWS_AS(dg::read_grammar(path), dg::InputError);
  std::filesystem::remove_all(folder);
}

TEST_CASE("resize CLI: unknown grid or count out of range exits 2 and writes nothing", "[synthesis][grid]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-resize-cli-test");
  const dg::test::AnalyzedModel fence = dg::test::analyze_model("fence_4", folder);
  REQUIRE(fence.run.status == 0);
  const std::string out = (folder / "out.obj").string();
  auto status_of = [&](const std::string& arguments) {
    return dg::test::run_cli("resize " + fence.grammar.string() + " " + arguments + " -o " + out, folder).status;
  };
  CHECK(status_of("--grid nosuch=3") == 2);
  CHECK(status_of("--grid grid1=-2") == 2);
  CHECK(status_of("--grid grid1=3x3") == 2);
  CHECK(status_of("--grid grid1=abc") == 2);
  CHECK_FALSE(std::filesystem::exists(out));
  CHECK(status_of("--grid grid1=6") == 0);
  CHECK(std::filesystem::exists(out));
  // A missing output folder is created, as generate and analyze do.
  const std::filesystem::path nested = folder / "new" / "folder" / "wide.obj";
  CHECK(dg::test::run_cli("resize " + fence.grammar.string() + " --grid grid1=6 -o " + nested.string(), folder).status == 0);
  CHECK(std::filesystem::exists(nested));
  std::filesystem::remove_all(folder);
}

TEST_CASE("resized_size counts every piece's copies, and the resize CLI refuses one past --max-triangles",
          "[synthesis][grid]") {
  const Grammar g = grammar_of("fence", {{"n", 4}});
  for (int n : {1, 4, 9, 40}) {
    CAPTURE(n);
    const std::vector<int> counts = counts_for(g.grid, {{Vec3(2, 0, 0), n}});
    std::size_t placed = 0;
    for (const dg::GridPiece& piece : g.pieces)
      placed += dg::piece_placements(g.grid, piece, counts).size() * piece.mesh.triangles.size();
    CHECK(dg::resized_size(g.grid, g.pieces, counts) == placed);
  }
  CHECK_THROWS_AS(dg::resized_size(g.grid, g.pieces, {1, 1}), dg::InputError);

  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-resize-limit-test");
  const dg::test::AnalyzedModel fence = dg::test::analyze_model("fence_4", folder);
  REQUIRE(fence.run.status == 0);
  const std::string out = (folder / "long.obj").string();
  const dg::test::CliRun refused =
      dg::test::run_cli("resize " + fence.grammar.string() + " --grid grid1=900 --max-triangles 20000 -o " + out, folder);
  CHECK(refused.status == 2);
  CHECK(refused.output.find("grid1=900 would place about") != std::string::npos);
  CHECK(refused.output.find("more than --max-triangles 20000") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(out));
  // generate refuses grid variants whose largest draw could pass --max-triangles, before it
  // makes its folder.
  const dg::ShapeGrammar grammar = dg::read_grammar(fence.grammar);
  dg::VariantOptions variant_options;
  variant_options.range_factor = 1.0;
  CHECK(dg::largest_grid_variant_size(grammar, variant_options) == grammar.exemplar.triangles.size());
  variant_options.range_factor = 100.0;
  const std::size_t largest = dg::largest_grid_variant_size(grammar, variant_options);
  CHECK(largest > 20 * grammar.exemplar.triangles.size());  // 4 units become 400
  const std::filesystem::path batch = folder / "batch";
  const dg::test::CliRun too_many = dg::test::run_cli("generate " + fence.grammar.string() +
                                                          " --rules grid --range-factor 100 --max-triangles 20000 --count 2 -o " +
                                                          batch.string(),
                                                      folder);
  CHECK(too_many.status == 2);
  CHECK(too_many.output.find(fmt::format("could place about {} triangles, more than --max-triangles 20000", largest)) !=
        std::string::npos);
  CHECK_FALSE(std::filesystem::exists(batch));
  // The default limit lets the longest fence the grid allows through.
  const dg::test::CliRun built = dg::test::run_cli("resize " + fence.grammar.string() + " --grid grid1=900 -q -o " + out, folder);
  CHECK(built.status == 0);
  CHECK(std::filesystem::exists(out));
  std::filesystem::remove_all(folder);
}

TEST_CASE("resize CLI: a count below the units a grid's head keeps exits 2 and says why", "[synthesis][grid]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-resize-kept-test");
  const dg::test::AnalyzedModel messy = dg::test::analyze_model("messy_facade_3x4", folder);
  REQUIRE(messy.run.status == 0);
  std::ifstream report(folder / "messy_facade_3x4.report.md");
  const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
  CHECK(text.find("2 units kept once in the head") != std::string::npos);
  CHECK(text.find("direction 1: 2..1000") != std::string::npos);
  const std::string out = (folder / "out.obj").string();
  const dg::test::CliRun low = dg::test::run_cli("resize " + messy.grammar.string() + " --grid grid1=1x3 -o " + out, folder);
  CHECK(low.status == 2);
  CHECK(low.output.find("head and tail keep 2 unit") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(out));
  const dg::test::CliRun quiet = dg::test::run_cli("resize " + messy.grammar.string() + " --grid grid1=2x3 -q -o " + out, folder);
  CHECK(quiet.status == 0);
  CHECK(quiet.output.empty());
  CHECK(std::filesystem::exists(out));
  std::filesystem::remove_all(folder);
}
