// Resizing a screw grid (spiral stairs): every added unit is the screw motion applied once more,
// and the grammar file keeps the motion.

#include "synthesis/grid_resize.h"

#include "assets/generator/asset.h"
#include "geometry/topology.h"
#include "grammar/grammar_file.h"
#include "support/mesh_distance.h"

#include <catch2/catch.hpp>

#include <filesystem>

namespace {

struct StairsGrammar {
  double eps = 0.0;
  dg::GridRule grid;
  std::vector<dg::GridPiece> pieces;
};

StairsGrammar stairs_grammar(int steps) {
  dg::Model model;
  model.mesh = dg::assets::make_asset("spiral_stairs", {{"steps", steps}}).mesh;
  const dg::PreparedModel prepared = dg::prepare_model(std::move(model));
  const std::vector<dg::GridRule> grids = dg::find_grids(prepared, dg::detect_symmetries(prepared));
  REQUIRE(grids.size() == 1);
  REQUIRE(grids[0].directions.size() == 1);
  return {prepared.surface.eps(), grids[0], dg::cut_grid_pieces(prepared.model.mesh, grids[0], prepared.surface.eps())};
}

void check_same_shape(const dg::TriangleMesh& result, const dg::TriangleMesh& expected, double eps) {
  CHECK(dg::is_closed_and_oriented(result));
  CHECK(dg::test::hausdorff_distance(result, expected) < eps);
  CHECK(result.area() == Approx(expected.area()).epsilon(1e-3));
}

}  // namespace

TEST_CASE("resize spiral stairs(12) to 16 steps gives the generator's stairs(16)", "[synthesis][grid]") {
  const StairsGrammar g = stairs_grammar(12);
  REQUIRE(g.grid.directions[0].count == 12);
  check_same_shape(dg::resize_grid(g.grid, g.pieces, {12}, 1e-6 * g.eps), dg::assets::make_asset("spiral_stairs", {{"steps", 12}}).mesh,
                   g.eps);
  check_same_shape(dg::resize_grid(g.grid, g.pieces, {16}, 1e-6 * g.eps), dg::assets::make_asset("spiral_stairs", {{"steps", 16}}).mesh,
                   g.eps);
  check_same_shape(dg::resize_grid(g.grid, g.pieces, {7}, 1e-6 * g.eps), dg::assets::make_asset("spiral_stairs", {{"steps", 7}}).mesh,
                   g.eps);
}

TEST_CASE("a screw grid survives the grammar file", "[synthesis][grid]") {
  const StairsGrammar g = stairs_grammar(12);
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "dockgrammar-screw-grid";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
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
  check_same_shape(dg::resize_grid(read.grids[0].rule, read.grids[0].pieces, {14}, 1e-6 * g.eps),
                   dg::assets::make_asset("spiral_stairs", {{"steps", 14}}).mesh, g.eps);
  std::filesystem::remove_all(folder);
}
