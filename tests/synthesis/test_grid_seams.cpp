// Seams of grid pieces that meet only approximately: measured, and welded within that distance.

#include "grammar/grid_seams.h"
#include "grammar/tolerance_hint.h"

#include "assets/generator/asset.h"
#include "geometry/topology.h"
#include "grammar/grammar_file.h"
#include "grammar/grid_cut.h"
#include "grammar/unused_repeats.h"
#include "support/cli_run.h"
#include "support/corpus.h"
#include "synthesis/grid_resize.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>

using dg::Vec3;

TEST_CASE("grid seams: a unit whose top seam lies off its neighbour's is measured and welded shut", "[synthesis][grid]") {
  dg::Model model;
  model.mesh = dg::assets::make_asset("fence", {{"n", 4}}).mesh;
  const dg::PreparedModel prepared = dg::prepare_model(std::move(model));
  const double eps = prepared.surface.eps();
  std::vector<dg::GridRule> grids = dg::find_grids(prepared, dg::detect_symmetries(prepared));
  REQUIRE(grids.size() == 1);
  dg::GridRule& grid = grids[0];
  REQUIRE(grid.directions.size() == 1);
  std::vector<dg::GridPiece> pieces = dg::cut_grid_pieces(prepared.model.mesh, grid, eps);

  // The generator's copies are exact: the seams meet up to rounding.
  CHECK(dg::grid_seam_misfit(grid, pieces, eps) < 1e-6 * eps);

  // Lift the unit's top seam (the rails' cross-sections on its upper plane) by 0.1 eps, as if
  // the exemplar's next unit were modelled that much higher there.
  const dg::GridDirection& d = grid.directions[0];
  const double top = d.cut + (d.head_units + 1) * d.pitch;
  const double lift = 0.1 * eps;
  std::size_t lifted = 0;
  for (dg::GridPiece& piece : pieces)
    if (piece.classes[0] == 1)
      for (Vec3& p : piece.mesh.positions)
        if (std::abs(d.direction.dot(p) - top) < 1e-9) {
          p.z() += lift;
          ++lifted;
        }
  REQUIRE(lifted > 0);
  grid.seam_misfit = dg::grid_seam_misfit(grid, pieces, eps);
  CHECK(grid.seam_misfit == Approx(lift).epsilon(1e-6));
  CHECK(dg::grid_weld_tolerance(grid, eps) == Approx(2.0 * lift).epsilon(1e-6));

  // Welded at float rounding (no misfit recorded), the lifted seams stay open; within the
  // measured misfit they close.
  const std::vector<int> counts{d.count + 2};
  dg::GridRule unmeasured = grid;
  unmeasured.seam_misfit = 0.0;
  CHECK(dg::edge_statistics(dg::resize_grid(unmeasured, pieces, counts, eps)).boundary_edges > 0);
  const dg::TriangleMesh welded = dg::resize_grid(grid, pieces, counts, eps);
  const dg::EdgeStatistics stats = dg::edge_statistics(welded);
  CHECK(stats.boundary_edges == 0);
  CHECK(stats.non_manifold_edges == 0);
}

TEST_CASE("corpus: the Scopia iron railing gives its 9 frames at a tolerance of 0.25 eps and resizes welded",
          "[synthesis][grid][corpus]") {
  const std::optional<std::filesystem::path> railing =
      dg::test::corpus_file_if_present("meshes/arch-scopia-iron-railing/iron-railing-1.obj");
  if (!railing) return;
  const dg::PreparedModel prepared = dg::prepare_model(*railing);
  const double eps = prepared.surface.eps();
  const Vec3 pitch(15.8506, 0, 0);  // two bars: one oval frame and its bars (SOURCES.md: 9 frames)
  auto frames = [&](const std::vector<dg::GridRule>& grids) -> const dg::GridRule* {
    for (const dg::GridRule& g : grids)
      if (g.directions.size() == 1 && ((g.directions[0].translation - pitch).norm() < 1e-3 ||
                                       (g.directions[0].translation + pitch).norm() < 1e-3))
        return &g;
    return nullptr;
  };
  // Exact matching: the hand-modelled scrolls and frames repeat only within about 0.2 eps, and
  // the planes fit 3 units.
  const dg::SymmetryResult exact_symmetries = dg::detect_symmetries(prepared);
  const std::vector<dg::GridRule> exact = dg::find_grids(prepared, exact_symmetries);
  REQUIRE(frames(exact) != nullptr);
  CHECK(frames(exact)->directions[0].count < 9);
  // analyze suggests the wider tolerance: the bar translation repeats 19 times and its
  // r-symmetric area grows by more than a fifth of the surface.
  std::vector<dg::GridWithPieces> exact_grids;
  for (const dg::GridRule& g : exact) exact_grids.push_back({g, {}});
  const std::optional<dg::ToleranceHint> hint = dg::tolerance_hint(prepared, exact_symmetries, exact_grids);
  REQUIRE(hint.has_value());
  CHECK(hint->repeats >= 18);
  CHECK(hint->grid_units == frames(exact)->directions[0].count);
  CHECK(hint->tolerance_eps == 0.25);
  CHECK(hint->r_symmetric_wider > hint->r_symmetric_now + 0.2);

  dg::SymmetryOptions tolerant;
  tolerant.region.offset_tolerance_eps = 0.25;
  const std::vector<dg::GridRule> grids = dg::find_grids(prepared, dg::detect_symmetries(prepared, tolerant));
  REQUIRE(frames(grids) != nullptr);
  dg::GridRule grid = *frames(grids);
  CHECK(grid.directions[0].count == 9);
  const std::vector<dg::GridPiece> pieces = dg::cut_grid_pieces(prepared.model.mesh, grid, eps);
  grid.seam_misfit = dg::grid_seam_misfit(grid, pieces, eps);
  CHECK(grid.seam_misfit > 1e-3 * eps);
  CHECK(grid.seam_misfit < 0.25 * eps);

  // 12 frames: welded at float rounding the seams between copies stay open; welded within the
  // measured misfit the result has no more open edges than the exemplar (32).
  const std::size_t exemplar_open = dg::edge_statistics(prepared.model.mesh).boundary_edges;
  dg::GridRule unmeasured = grid;
  unmeasured.seam_misfit = 0.0;
  const dg::EdgeStatistics loose = dg::edge_statistics(dg::resize_grid(unmeasured, pieces, {12}, eps));
  const dg::EdgeStatistics welded = dg::edge_statistics(dg::resize_grid(grid, pieces, {12}, eps));
  CHECK(loose.boundary_edges > exemplar_open + 100);
  CHECK(welded.boundary_edges <= exemplar_open);
  CHECK(welded.non_manifold_edges == 0);
}

TEST_CASE("corpus: the Quaternius bank's colonnade hint suggests half an eps, which gives its grid",
          "[synthesis][grid][corpus]") {
  const std::optional<std::filesystem::path> bank = dg::test::corpus_file_if_present("meshes/arch-quaternius-bank/bank.obj");
  if (!bank) return;
  const dg::PreparedModel prepared = dg::prepare_model(*bank);
  const dg::SymmetryResult exact = dg::detect_symmetries(prepared);
  REQUIRE(dg::find_grids(prepared, exact).empty());
  // The columns stand about 54 apart along both colonnades, but splay: the pitch is 53.99 at
  // the bases and 54.81 at the abaci (0.48 eps more). A quarter eps adds under 5 % of the
  // surface, half an eps about 9 %.
  const std::optional<dg::ToleranceHint> hint = dg::tolerance_hint(prepared, exact, {});
  REQUIRE(hint.has_value());
  CHECK(hint->tolerance_eps == 0.5);
  CHECK(hint->grid_units == 0);
  const dg::SymmetryFamily& colonnade = exact.families[hint->family];
  CHECK(colonnade.kind == "translation");
  CHECK(std::abs(colonnade.generator.translation.norm() - 54.0) < 1.0);
  CHECK(hint->r_symmetric_wider > hint->r_symmetric_now + 0.05);

  dg::SymmetryOptions tolerant;
  tolerant.region.offset_tolerance_eps = hint->tolerance_eps;
  const std::vector<dg::GridRule> grids = dg::find_grids(prepared, dg::detect_symmetries(prepared, tolerant));
  REQUIRE(grids.size() == 1);
  REQUIRE(grids[0].directions.size() == 1);
  CHECK(std::abs(grids[0].directions[0].translation.norm() - 54.0) < 1.0);
  CHECK(grids[0].directions[0].count >= 3);
}

TEST_CASE("corpus: no tolerance hint for the Blendswap radiator whose fins differ in shape and its short grid named",
          "[synthesis][grid][corpus]") {
  const std::optional<std::filesystem::path> radiator = dg::test::corpus_file_if_present("meshes/furn-blendswap-radiator1/radiator1.obj");
  if (!radiator) return;
  const dg::PreparedModel prepared = dg::prepare_model(*radiator);
  const dg::SymmetryResult symmetries = dg::detect_symmetries(prepared);
  std::vector<dg::GridWithPieces> grids;
  for (const dg::GridRule& g : dg::find_grids(prepared, symmetries)) grids.push_back({g, {}});
  // Its fin translation repeats 27 times over a grid of 2 units, but the fins' bevels differ in
  // angle, not position: a wider position tolerance adds under 1 % of the surface.
  CHECK_FALSE(dg::tolerance_hint(prepared, symmetries, grids).has_value());
  // Wall brackets joined to the panel cross the fins, so the grid (2 units of two fins, and one
  // more kept once, whose fins' flat faces are copies of the unit's though its slab is not) spans
  // 6 of the 27 repeats: the report names the fin translation as used for only part of them.
  std::vector<dg::GridRule> rules;
  for (const dg::GridWithPieces& g : grids) rules.push_back(g.rule);
  const dg::UnusedRepeats unused = dg::unused_repeats(symmetries, rules, dg::GridOptions{}.min_repeats);
  REQUIRE(unused.short_runs.size() == 1);
  const dg::SymmetryFamily& fins = symmetries.families[unused.short_runs[0].family];
  CHECK(fins.count == 27);
  CHECK(fins.generator.translation.norm() == Approx(6.7).epsilon(0.01));
  CHECK(unused.short_runs[0].spanned == Approx(6.0).epsilon(0.01));
}

TEST_CASE("analyze --tolerance: the summary and report give the tolerance and the grammar keeps the grid's seam misfit",
          "[synthesis][grid][tools]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-tolerance-test");
  const dg::test::AnalyzedModel fence = dg::test::analyze_model("fence_4", folder, "--tolerance 0.25 --json");
  REQUIRE(fence.run.status == 0);
  const nlohmann::json summary = nlohmann::json::parse(fence.run.output);
  CHECK(summary["tolerance"].get<double>() == 0.25);
  const dg::test::CliRun symmetry = dg::test::run_cli(
      "symmetry " + std::string(DOCKGRAMMAR_SOURCE_DIR) + "/assets/models/fence_4.obj -q --json --tolerance 0.2", folder);
  REQUIRE(symmetry.status == 0);
  CHECK(nlohmann::json::parse(symmetry.output)["tolerance"].get<double>() == 0.2);
  REQUIRE(summary["grids"].size() == 1);
  CHECK(summary["grids"][0]["counts"] == nlohmann::json::array({4}));
  std::ifstream report(folder / "fence_4.report.md");
  const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
  CHECK(text.find("within 1° and 0.25 eps") != std::string::npos);
  CHECK(text.find("their seams lie up to") != std::string::npos);

  // The grammar file keeps the measured misfit (the generator's copies are exact) and refuses a
  // negative one.
  const dg::ShapeGrammar grammar = dg::read_grammar(fence.grammar);
  REQUIRE(grammar.grids.size() == 1);
  CHECK(grammar.grids[0].rule.seam_misfit == summary["grids"][0]["seam_misfit"].get<double>());
  CHECK(grammar.grids[0].rule.seam_misfit < 1e-6 * grammar.eps);
  std::ifstream in(fence.grammar);
  nlohmann::json document = nlohmann::json::parse(in);
  document["grids"][0]["seam_misfit"] = -1.0;
  const std::filesystem::path broken = folder / "broken.grammar.json";
  std::ofstream(broken) << document.dump();
  CHECK_THROWS_WITH(dg::read_grammar(broken), Catch::Contains("seam_misfit that is not a finite number >= 0"));
  std::filesystem::remove_all(folder);
}

TEST_CASE("corpus: the spiral staircase resized by one step closes its seams within the measured misfit",
          "[synthesis][grid][corpus]") {
  const std::optional<std::filesystem::path> stairs =
      dg::test::corpus_file_if_present("meshes/arch-sh3d-spiral-staircase/spiralStaircase.obj");
  if (!stairs) return;
  const dg::PreparedModel prepared = dg::prepare_model(*stairs);
  const double eps = prepared.surface.eps();
  std::vector<dg::GridRule> grids = dg::find_grids(prepared, dg::detect_symmetries(prepared));
  REQUIRE(grids.size() == 1);
  dg::GridRule& grid = grids[0];
  REQUIRE(grid.directions.size() == 1);
  const std::vector<dg::GridPiece> pieces = dg::cut_grid_pieces(prepared.model.mesh, grid, eps);
  // Its handrail is swept in 8-degree segments under a 22.5-degree screw: the seams of copied
  // steps meet only within a fraction of eps.
  grid.seam_misfit = dg::grid_seam_misfit(grid, pieces, eps);
  CHECK(grid.seam_misfit > 0.01 * eps);
  CHECK(grid.seam_misfit < 0.5 * eps);
  const std::size_t exemplar_open = dg::edge_statistics(prepared.model.mesh).boundary_edges;  // 244
  const std::vector<int> one_more{grid.directions[0].count + 1};
  dg::GridRule unmeasured = grid;
  unmeasured.seam_misfit = 0.0;
  // Welded at float rounding, about 800 seam edges stay open; within the misfit, the open edges
  // are the exemplar's and one more step's share of them.
  const std::size_t loose = dg::edge_statistics(dg::resize_grid(unmeasured, pieces, one_more, eps)).boundary_edges;
  const dg::EdgeStatistics welded = dg::edge_statistics(dg::resize_grid(grid, pieces, one_more, eps));
  CHECK(loose > 2 * exemplar_open);
  CHECK(welded.boundary_edges <= exemplar_open + exemplar_open / 12 + 4);
  CHECK(welded.non_manifold_edges == 0);
}
