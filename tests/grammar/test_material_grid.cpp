// Patterns that exist only in materials: a flat wall with windows painted on it has no geometric
// repetition (every in-plane slide maps the plane onto itself), but with --match-materials the
// window grid is found along the pitches the wall was drawn with.

#include "grammar/grid_rules.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

namespace {

constexpr double kPitchX = 3.0, kPitchY = 2.0;

/// Axis-aligned rectangle [x0, x1] x [y0, y1] in the plane z = 0 as two front-facing triangles.
void add_rectangle(dg::TriangleMesh& mesh, double x0, double y0, double x1, double y1, std::uint32_t material) {
  const auto base = static_cast<std::uint32_t>(mesh.positions.size());
  for (const auto& [x, y] : {std::pair{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}) mesh.positions.emplace_back(x, y, 0.0);
  mesh.triangles.push_back({base, base + 1, base + 2});
  mesh.triangles.push_back({base, base + 2, base + 3});
  mesh.materials.insert(mesh.materials.end(), 2, material);
}

/// A wall of `columns` x `rows` cells, each a window (material 1) framed by wall (material 0),
/// welded by prepare_model's cleaning into one flat sheet.
dg::Model painted_wall(int columns, int rows) {
  dg::Model model;
  model.materials = {{"wall", dg::Vec3(0.9, 0.9, 0.85)}, {"glass", dg::Vec3(0.3, 0.4, 0.6)}};
  // Cell-local x and y breaks: frame, window, frame.
  const double xs[] = {0.0, 0.75, 2.25, kPitchX}, ys[] = {0.0, 0.5, 1.5, kPitchY};
  for (int c = 0; c < columns; ++c)
    for (int r = 0; r < rows; ++r)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          add_rectangle(model.mesh, c * kPitchX + xs[i], r * kPitchY + ys[j], c * kPitchX + xs[i + 1],
                        r * kPitchY + ys[j + 1], i == 1 && j == 1 ? 1 : 0);
  return model;
}

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
    // Identical cells with nothing different at the ends: the head and the tail together make one
    // cell, so n cells are n - 1 repeated units (as with the Kenney gate's identical stakes).
    CHECK(found[0].second == rows - 1);
    CHECK(std::abs(found[1].first - kPitchX) < 1e-6);
    CHECK(found[1].second == columns - 1);

    const dg::PreparedModel geometry_only = dg::prepare_model(painted_wall(columns, rows));
    CHECK(dg::find_grids(geometry_only, dg::detect_symmetries(geometry_only)).empty());
  }
}
