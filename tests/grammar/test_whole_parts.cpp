#include "grammar/whole_parts.h"

#include "geometry/model_io.h"
#include "grammar/grid_cut.h"
#include "grammar/grid_rules.h"
#include "support/cli_run.h"
#include "support/corpus.h"
#include "support/shapes.h"
#include "synthesis/grid_resize.h"
#include "synthesis/verify.h"

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <optional>

using dg::Vec3;

namespace {

// The grid's pieces resized to `count` units, checked r-similar to the exemplar.
void check_resized_verifies(const dg::PreparedModel& prepared, const dg::GridRule& grid, int count) {
  const std::vector<dg::GridPiece> pieces = dg::cut_grid_pieces(prepared.model.mesh, grid, prepared.surface.eps());
  dg::Model exemplar, resized;
  exemplar.mesh = prepared.model.mesh;
  resized.mesh = dg::resize_grid(grid, pieces, {count}, prepared.surface.eps());
  const dg::VerifyReport report = dg::verify_models(std::move(exemplar), std::move(resized));
  INFO(count << " units: " << report.similarity.similar << " of " << report.similarity.samples << " samples r-similar");
  CHECK(report.pass);
}

// A rail (20 x 1 x 1 along x) with 5 equal blocks (1 x 1 x 0.8) on it every 4 units, and along
// each gap between two blocks a separate low bar, each at another depth: a row of parts whose every
// gap holds a part that repeats nowhere, so no plane across the whole model between two blocks
// crosses only symmetric area (and planes through the blocks enclose a bar each).
dg::TriangleMesh row_with_odd_parts() {
  dg::TriangleMesh mesh = dg::test::make_box({0, 0, 0}, {20, 1, 1});
  for (int k = 0; k < 5; ++k) {
    const double x = 1.25 + 4.0 * k;
    dg::test::append(mesh, dg::test::make_box({x, 1, 0.1}, {x + 1.0, 2.0, 0.9}));
  }
  for (int k = 0; k < 4; ++k) {
    const double start = 2.25 + 4.0 * k + 0.4, depth = 0.15 + 0.1 * k;
    dg::test::append(mesh, dg::test::make_box({start, 1, depth}, {start + 2.2, 1.2, depth + 0.2}));
  }
  return mesh;
}

}  // namespace

TEST_CASE("a row of parts gives a 1-grid that keeps the odd parts in its gaps whole", "[grammar][grid][whole_parts]") {
  dg::Model model;
  model.mesh = row_with_odd_parts();
  const dg::PreparedModel prepared = dg::prepare_model(dg::Model(model));
  const dg::SymmetryResult symmetries = dg::detect_symmetries(prepared);
  const std::vector<dg::GridRule> grids = dg::find_grids(prepared, symmetries);
  // Planes across the whole model find no grid here: each gap holds a bar at a depth of its own.
  REQUIRE(grids.size() == 1);
  const dg::GridRule& grid = grids.front();
  REQUIRE(grid.directions.size() == 1);
  const dg::GridDirection& row = grid.directions.front();
  CHECK(std::abs(std::abs(row.translation.x()) - 4.0) < 1e-3);
  CHECK(row.translation.tail<2>().norm() < 1e-3);
  CHECK(row.count >= 3);
  // The 4 bars (12 triangles each) are kept whole, and perhaps a block at an end of the row.
  const std::size_t whole = row.whole_in_head.size() + row.whole_in_tail.size();
  CHECK(whole >= 4 * 12);
  CHECK(lowest_count(grid, 0) <= row.count);

  // Its pieces rebuild the exemplar, and two more units stay r-similar to it.
  const std::vector<dg::GridPiece> pieces = dg::cut_grid_pieces(prepared.model.mesh, grid, prepared.surface.eps());
  const dg::TriangleMesh own = dg::resize_grid(grid, pieces, {row.count}, prepared.surface.eps());
  CHECK(own.area() == Approx(prepared.model.mesh.area()).epsilon(1e-3));
  check_resized_verifies(prepared, grid, row.count + 2);
}

TEST_CASE("analyze names the parts a grid keeps whole, and resize refuses counts that bring them within r",
          "[tools][grid][whole_parts]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-whole-parts-cli");
  dg::write_mesh(folder / "row.obj", row_with_odd_parts());
  const dg::test::CliRun analyzed = dg::test::run_cli("analyze " + (folder / "row.obj").string() + " -q --json -o " + folder.string(), folder);
  REQUIRE(analyzed.status == 0);
  const nlohmann::json summary = nlohmann::json::parse(analyzed.output);
  REQUIRE(summary["grids"].size() == 1);
  const nlohmann::json& grid = summary["grids"][0];
  const nlohmann::json& kept = grid["parts_kept_whole"][0];
  CHECK(kept["head"].get<int>() + kept["tail"].get<int>() >= 4);  // the 4 bars, perhaps an end block
  std::ifstream report(folder / "row.report.md");
  const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
  CHECK(text.find("separate parts kept whole") != std::string::npos);
  const int lowest = grid["min_counts"][0].get<int>();
  REQUIRE(lowest > 0);  // the bars in the head and in the tail would meet further down
  const dg::test::CliRun refused = dg::test::run_cli(
      "resize " + (folder / "row.grammar.json").string() + " --grid grid1=" + std::to_string(lowest - 1) + " -o " +
          (folder / "short.obj").string(),
      folder);
  CHECK(refused.status == 2);
  CHECK(refused.output.find("outside the allowed range") != std::string::npos);
  std::filesystem::remove_all(folder);
}

TEST_CASE("corpus: the Scopia iron railing gives a 1-grid of two scroll pitches that keeps its bars whole",
          "[grammar][grid][whole_parts][corpus]") {
  // Its scroll bands repeat every 7.925, its bars every 16.0: no plane across the whole railing
  // crosses only symmetric area, so it had no grid. The bars are separate parts.
  const std::optional<std::filesystem::path> path = dg::test::corpus_file_if_present("meshes/arch-scopia-iron-railing/iron-railing-1.obj");
  if (!path) return;
  const dg::PreparedModel prepared = dg::prepare_model(*path);
  const std::vector<dg::GridRule> grids = dg::find_grids(prepared, dg::detect_symmetries(prepared));
  REQUIRE(grids.size() == 1);
  REQUIRE(grids[0].directions.size() == 1);
  const dg::GridDirection& row = grids[0].directions[0];
  CHECK(std::abs(row.pitch - 2 * 7.925) < 0.01);
  CHECK(row.count >= 3);
  CHECK_FALSE(row.whole_in_tail.empty());
  check_resized_verifies(prepared, grids[0], row.count + 3);
}
