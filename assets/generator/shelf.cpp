// shelf(columns, rows): a bookshelf box open to the front (-y) with columns x rows cells, i.e.
// columns-1 vertical and rows-1 horizontal dividers fused with the frame, a back panel, and a
// recessed plinth (toe kick) under the bottom board, leaving a foot at each side. Outer boards
// are thicker than dividers, so corner, border and interior pieces differ.
//
// Column i is the slab x in [side + i*px - d/2, side + (i+1)*px - d/2) (a cell with half a
// divider on each side, px = cell_width + d); row j likewise along z above the plinth and the
// bottom board. counts = (columns, rows).

#include "assets/generator/box_solid.h"
#include "assets/generator/ground_truth.h"
#include "assets/generator/models.h"

#include <fmt/format.h>
#include <limits>

namespace dg::assets {

namespace {

constexpr double kBoard = 0.025;       // outer boards (sides, top, bottom), m
constexpr double kDivider = 0.018;     // dividers between cells
constexpr double kBack = 0.006;        // back panel
constexpr double kPlinth = 0.07;       // plinth height under the bottom board
constexpr double kToeRecess = 0.03;    // plinth set back from the front

}  // namespace

Asset make_shelf(const nlohmann::json& params) {
  Parameters p = read_parameters("shelf", params);
  const int columns = integer_parameter(p, "columns", 3, 1, 1000);
  const int rows = integer_parameter(p, "rows", 4, 1, 1000);
  const double cell_width = number_parameter(p, "cell_width", 0.35, 0.05, 10.0);
  const double cell_height = number_parameter(p, "cell_height", 0.30, 0.05, 10.0);
  const double depth = number_parameter(p, "depth", 0.30, 0.05, 10.0);
  const int detail = integer_parameter(p, "detail", 1, 1, 1000);
  reject_unknown_parameters(p);

  const double px = cell_width + kDivider, pz = cell_height + kDivider;
  const double width = 2 * kBoard + columns * px - kDivider;
  const double bottom = kPlinth + kBoard;  // floor of the lowest cells
  const double height = bottom + rows * pz - kDivider + kBoard;
  BoxSolid solid;
  add_box(solid, Vec3(0.0, 0.0, 0.0), Vec3(width, depth, height));
  // The toe recess stops half a board from each side, outside the column slabs (see below).
  subtract_box(solid, Vec3(kBoard / 2, 0.0, 0.0), Vec3(width - kBoard / 2, kToeRecess, kPlinth));
  for (int i = 0; i < columns; ++i) {
    for (int j = 0; j < rows; ++j) {
      const Vec3 lo(kBoard + i * px, 0.0, bottom + j * pz);
      subtract_box(solid, lo, Vec3(lo.x() + cell_width, depth - kBack, lo.z() + cell_height));
    }
  }
  for (int i = 0; i <= columns; ++i) add_seam(solid, 0, kBoard + i * px - kDivider / 2);
  for (int j = 0; j <= rows; ++j) add_seam(solid, 2, bottom + j * pz - kDivider / 2);
  TriangleMesh mesh = box_solid_surface(solid, detail);

  const double inf = std::numeric_limits<double>::infinity();
  const double x0 = kBoard - kDivider / 2, z0 = bottom - kDivider / 2;
  Repetition column_rep = translation_repetition(
      "columns", Vec3(px, 0.0, 0.0), columns,
      "column i: slab x in [board + i*px - divider/2, board + (i+1)*px - divider/2), px = cell_width + divider: "
      "`rows` cells, half a divider each side, the top and bottom board and plinth below; count = columns");
  column_rep.measure = measure_unit(mesh, box_region(Vec3(x0, -inf, -inf), Vec3(x0 + px, inf, inf)));
  Repetition row_rep = translation_repetition(
      "rows", Vec3(0.0, 0.0, pz), rows,
      "row j: slab z in [plinth + board + j*pz - divider/2, ... + pz), pz = cell_height + divider: `columns` "
      "cells, half a divider above and below, the side boards; count = rows");
  row_rep.measure = measure_unit(mesh, box_region(Vec3(-inf, -inf, z0), Vec3(inf, inf, z0 + pz)));
  const UnitMeasure cell = measure_unit(mesh, box_region(Vec3(x0, -inf, z0), Vec3(x0 + px, inf, z0 + pz)));

  const nlohmann::json grids =
      nlohmann::json::array({grid_json(column_rep, row_rep, cell, "one open cell with half a divider on each side")});
  const nlohmann::json notes = {
      {"description", "bookshelf open to -y: frame, dividers, back panel, recessed plinth"},
      {"dimensions",
       {{"board", kBoard}, {"divider", kDivider}, {"back_panel", kBack}, {"plinth", kPlinth}, {"toe_recess", kToeRecess}}}};
  return finish_asset(fmt::format("shelf_{}x{}", columns, rows), p, std::move(mesh), {column_rep, row_rep}, grids, notes);
}

}  // namespace dg::assets
