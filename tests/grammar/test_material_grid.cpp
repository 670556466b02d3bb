// Patterns that exist only in materials: a flat wall with windows painted on it has no geometric
// repetition (every in-plane slide maps the plane onto itself), but with --match-materials the
// window grid is found along the pitches the wall was drawn with.

#include "grammar/grid_rules.h"

#include "support/material_models.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

namespace {

constexpr double kPitchX = dg::test::kPaintedPitchX, kPitchY = dg::test::kPaintedPitchY;
using dg::test::painted_wall;

}  // namespace

TEST_CASE("painted wall: a 2-grid of windows with --match-materials, none from geometry alone", "[grammar][grid]") {
  for (const auto& [columns, rows] : {std::pair{6, 4}, {7, 5}}) {
    INFO(columns << " x " << rows);
    dg::PrepareOptions options;
    options.match_materials = true;
    const dg::PreparedModel prepared = dg::prepare_model(painted_wall(columns, rows), options);
    const std::vector<dg::GridRule> grids = dg::find_grids(prepared, dg::detect_symmetries(prepared));
    REQUIRE(grids.size() == 1);
    REQUIRE(grids[0].directions.size() == 2);
    std::vector<std::pair<double, int>> found;
    for (const auto& direction : grids[0].directions) found.emplace_back(direction.pitch, direction.count);
    std::sort(found.begin(), found.end());
    CHECK(std::abs(found[0].first - kPitchY) < 1e-6);
    // Identical cells with nothing different at the ends: planes at the cells' borders keep every
    // cell whole, so n cells are n units (the ends count as copies beyond the planes).
    CHECK(found[0].second == rows);
    CHECK(std::abs(found[1].first - kPitchX) < 1e-6);
    CHECK(found[1].second == columns);

    const dg::PreparedModel geometry_only = dg::prepare_model(painted_wall(columns, rows));
    CHECK(dg::find_grids(geometry_only, dg::detect_symmetries(geometry_only)).empty());
  }
}
