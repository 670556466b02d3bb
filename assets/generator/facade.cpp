// facade(columns, rows): a wall slab facing -y with a ground floor, `rows` upper storeys and a
// cornice. Every column has one door recess in the ground floor (cut through a base band) and
// one window recess per upper storey. Corner, border and interior pieces differ: side margins
// are plain wall, the bottom border holds the doors and the base band, the top border the
// parapet and the cornice (which overhangs the front and both sides).
//
// Column k (k = 0 .. columns-1) is the slab x in [margin + k*px, margin + (k+1)*px); row r
// (r = 0 .. rows-1) is the storey z in [ground + r*pz, ground + (r+1)*pz). A 2-grid cell is
// their intersection: one window with the wall around it. counts = (columns, rows), so
// facade(3, 4) resized to 5 x 7 is facade(5, 7).

#include "assets/generator/box_solid.h"
#include "assets/generator/ground_truth.h"
#include "assets/generator/models.h"

#include <fmt/format.h>
#include <limits>

namespace dg::assets {

namespace {

constexpr double kMargin = 1.0;          // plain wall left and right of the columns, m
constexpr double kThickness = 0.30;      // wall, along +y (front face at y = 0)
constexpr double kGroundHeight = 4.0;    // ground floor storey
constexpr double kParapet = 0.6;         // wall above the last storey
constexpr double kDoorWidth = 1.4;
constexpr double kDoorHeight = 2.6;
constexpr double kDoorDepth = 0.2;       // recess behind the front face
constexpr double kBandHeight = 0.5;      // base band at the bottom, protruding
constexpr double kBandDepth = 0.1;
constexpr double kWindowWidth = 1.2;
constexpr double kWindowHeight = 1.5;
constexpr double kSill = 0.9;            // window bottom above the storey floor
constexpr double kWindowDepth = 0.15;
constexpr double kCorniceHeight = 0.4;
constexpr double kCorniceOverhang = 0.3;

}  // namespace

Asset make_facade(const nlohmann::json& params) {
  Parameters p = read_parameters("facade", params);
  const int columns = integer_parameter(p, "columns", 3, 1, 1000);
  const int rows = integer_parameter(p, "rows", 4, 1, 1000);
  const double px = number_parameter(p, "column_pitch", 3.0, 1.6, 100.0);
  const double pz = number_parameter(p, "row_pitch", 3.0, 2.7, 100.0);
  const int detail = integer_parameter(p, "detail", 1, 1, 1000);
  reject_unknown_parameters(p);

  const double width = 2 * kMargin + columns * px;
  const double height = kGroundHeight + rows * pz + kParapet;
  BoxSolid solid;
  add_box(solid, Vec3(0.0, 0.0, 0.0), Vec3(width, kThickness, height));
  add_box(solid, Vec3(0.0, -kBandDepth, 0.0), Vec3(width, 0.0, kBandHeight));
  for (int k = 0; k < columns; ++k) {
    const double x = kMargin + (k + 0.5) * px;
    subtract_box(solid, Vec3(x - kDoorWidth / 2, -kBandDepth, 0.0), Vec3(x + kDoorWidth / 2, kDoorDepth, kDoorHeight));
    for (int r = 0; r < rows; ++r) {
      const double z = kGroundHeight + r * pz + kSill;
      subtract_box(solid, Vec3(x - kWindowWidth / 2, 0.0, z), Vec3(x + kWindowWidth / 2, kWindowDepth, z + kWindowHeight));
    }
  }
  add_box(solid, Vec3(-kCorniceOverhang, -kCorniceOverhang, height - kCorniceHeight),
          Vec3(width + kCorniceOverhang, kThickness, height));
  for (int k = 0; k <= columns; ++k) add_seam(solid, 0, kMargin + k * px);
  for (int r = 0; r <= rows; ++r) add_seam(solid, 2, kGroundHeight + r * pz);
  TriangleMesh mesh = box_solid_surface(solid, detail);

  const double inf = std::numeric_limits<double>::infinity();
  const Vec3 column_lo(kMargin, -inf, -inf), column_hi(kMargin + px, inf, inf);
  const Vec3 row_lo(-inf, -inf, kGroundHeight), row_hi(inf, inf, kGroundHeight + pz);
  Repetition column_rep = translation_repetition(
      "columns", Vec3(px, 0.0, 0.0), columns,
      "column k: slab x in [margin + k*column_pitch, margin + (k+1)*column_pitch) holding one door, `rows` "
      "windows, the base band, parapet and cornice above them; count = columns");
  column_rep.measure = measure_unit(mesh, box_region(column_lo, column_hi));
  Repetition row_rep = translation_repetition(
      "rows", Vec3(0.0, 0.0, pz), rows,
      "row r: storey z in [ground + r*row_pitch, ground + (r+1)*row_pitch) over the full width, holding "
      "`columns` windows and the two side margins; count = rows (the ground floor is not counted)");
  row_rep.measure = measure_unit(mesh, box_region(row_lo, row_hi));
  const UnitMeasure cell = measure_unit(mesh, box_region(Vec3(column_lo.x(), -inf, row_lo.z()), Vec3(column_hi.x(), inf, row_hi.z())));

  const nlohmann::json grids = nlohmann::json::array(
      {grid_json(column_rep, row_rep, cell, "one window recess with the wall around it (column 0, row 0)")});
  const nlohmann::json notes = {
      {"description", "wall facing -y with ground floor doors, window rows and a cornice"},
      {"dimensions",
       {{"margin", kMargin}, {"wall_thickness", kThickness}, {"ground_floor_height", kGroundHeight},
        {"parapet", kParapet}, {"window", {kWindowWidth, kWindowHeight, kWindowDepth}},
        {"door", {kDoorWidth, kDoorHeight, kDoorDepth}}, {"cornice_height", kCorniceHeight},
        {"cornice_overhang", kCorniceOverhang}}}};
  return finish_asset(fmt::format("facade_{}x{}", columns, rows), p, std::move(mesh), {column_rep, row_rep}, grids, notes);
}

}  // namespace dg::assets
