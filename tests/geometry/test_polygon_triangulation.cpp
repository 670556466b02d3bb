#include "geometry/model_io.h"
#include "geometry/polygon_triangulation.h"
#include "support/cli_run.h"
#include "support/corpus.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

using dg::Vec3;

namespace {

// A comb in the plane y = 2, corners as (x, z): a strip 10 x 2 with four teeth 1 wide and 4 long,
// like a colonnade's floor notched around column plinths; counter-clockwise in (x, z), so it
// turns about -y.
const std::vector<std::pair<double, double>> comb = {{0, 0}, {10, 0}, {10, 6}, {9, 6}, {9, 2}, {7, 2}, {7, 6}, {6, 6},
                                                     {6, 2}, {4, 2}, {4, 6}, {3, 6}, {3, 2}, {1, 2}, {1, 6}, {0, 6}};
constexpr double comb_area = 10.0 * 2.0 + 4 * 1.0 * 4.0;

std::vector<Vec3> comb_positions() {
  std::vector<Vec3> positions;
  for (const auto& [x, z] : comb) positions.emplace_back(x, 2.0, z);
  return positions;
}

// Whether (x, z) lies inside the comb (crossings of a ray towards +x).
bool inside_comb(double x, double z) {
  bool inside = false;
  for (std::size_t i = 0, j = comb.size() - 1; i < comb.size(); j = i++) {
    const auto [xi, zi] = comb[i];
    const auto [xj, zj] = comb[j];
    if ((zi > z) != (zj > z) && x < xi + (z - zi) * (xj - xi) / (zj - zi)) inside = !inside;
  }
  return inside;
}

// Checks that `triangles` tile the comb: n - 2 of them, each turning as the polygon does, each
// inside it, their areas summing to the comb's.
void require_tiles_comb(const std::vector<Vec3>& positions, const std::vector<dg::Triangle>& triangles) {
  REQUIRE(triangles.size() == comb.size() - 2);
  const Vec3 polygon_normal(0.0, -1.0, 0.0);  // (x, z) counter-clockwise turns about -y
  double area = 0.0;
  for (const dg::Triangle& t : triangles) {
    const Vec3 a = positions[t[0]], b = positions[t[1]], c = positions[t[2]];
    const double signed_area = 0.5 * (b - a).cross(c - a).dot(polygon_normal);
    CHECK(signed_area > 0.0);
    const Vec3 centroid = (a + b + c) / 3.0;
    CHECK(inside_comb(centroid.x(), centroid.z()));
    area += signed_area;
  }
  CHECK(area == Approx(comb_area).epsilon(1e-12));
}

// A triangle's height over its longest side (model units): about zero for a needle.
double height_over_longest_side(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  return (b - a).cross(c - a).norm() / longest;
}

std::set<std::multiset<std::uint32_t>> corner_sets(const std::vector<dg::Triangle>& triangles) {
  std::set<std::multiset<std::uint32_t>> sets;
  for (const dg::Triangle& t : triangles) sets.insert({t[0], t[1], t[2]});
  return sets;
}

}  // namespace

TEST_CASE("polygon triangulation: a notched polygon's triangles stay inside it, a convex one keeps its fan",
          "[geometry]") {
  const std::vector<Vec3> positions = comb_positions();
  std::vector<std::uint32_t> corners(comb.size());
  for (std::uint32_t i = 0; i < corners.size(); ++i) corners[i] = i;
  const std::vector<dg::Triangle> triangles = dg::triangulate_polygon(positions, corners);
  require_tiles_comb(positions, triangles);
  // Started at any corner, the same triangles.
  std::vector<std::uint32_t> rotated = corners;
  std::rotate(rotated.begin(), rotated.begin() + 5, rotated.end());
  CHECK(corner_sets(dg::triangulate_polygon(positions, rotated)) == corner_sets(triangles));
  // Its back-to-back copy (corners in the opposite order) gets the same corner sets, turned over.
  std::vector<std::uint32_t> reversed(corners.rbegin(), corners.rend());
  const std::vector<dg::Triangle> back = dg::triangulate_polygon(positions, reversed);
  CHECK(corner_sets(back) == corner_sets(triangles));
  for (const dg::Triangle& t : back)
    CHECK((positions[t[1]] - positions[t[0]]).cross(positions[t[2]] - positions[t[0]]).y() > 0.0);

  // A convex hexagon: its fan, unchanged.
  std::vector<Vec3> hexagon;
  for (int i = 0; i < 6; ++i) hexagon.emplace_back(std::cos(i * 1.0472), std::sin(i * 1.0472), 0.5);
  const std::vector<std::uint32_t> hexagon_corners = {3, 4, 5, 0, 1, 2};
  const std::vector<dg::Triangle> expected = {{3, 4, 5}, {3, 5, 0}, {3, 0, 1}, {3, 1, 2}};
  CHECK(dg::triangulate_polygon(hexagon, hexagon_corners) == expected);

  // Degenerate and self-intersecting polygons still give n - 2 triangles of their corners.
  const std::vector<Vec3> line = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
  CHECK(dg::triangulate_polygon(line, std::vector<std::uint32_t>{0, 1, 2, 3, 4}).size() == 3);
  const std::vector<Vec3> bow_tie = {{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 2, 0}, {1, 3, 0}};
  const std::vector<dg::Triangle> tie = dg::triangulate_polygon(bow_tie, std::vector<std::uint32_t>{0, 1, 2, 3, 4});
  CHECK(tie.size() == 3);
  for (const dg::Triangle& t : tie)
    for (std::uint32_t c : t) CHECK(c < 5);
  const std::vector<Vec3> not_finite = {{0, 0, 0}, {1, 0, 0}, {NAN, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0}};
  CHECK(dg::triangulate_polygon(not_finite, std::vector<std::uint32_t>{0, 1, 2, 3, 4}).size() == 3);
}

TEST_CASE("model files: a notched n-gon in OBJ, OFF or PLY reads as triangles inside it (OBJ vertices may follow it)",
          "[geometry][model_io]") {
  // The fan from the first corner covered the notches: the Quaternius bank's colonnade floor and
  // ceiling, notched around the plinths and capitals, read 215 such polygons.
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-io-notched");
  std::ostringstream indices, points, obj_face, obj_vertices;
  obj_face << "f";
  for (std::size_t i = 0; i < comb.size(); ++i) {
    indices << ' ' << i;
    obj_face << ' ' << i + 1;
    points << comb[i].first << " 2 " << comb[i].second << '\n';
    obj_vertices << "v " << comb[i].first << " 2 " << comb[i].second << '\n';
  }
  std::ofstream(folder / "comb.obj") << obj_face.str() << "\n" << obj_vertices.str();  // faces may name vertices read later
  std::ofstream(folder / "comb.off") << "OFF\n" << comb.size() << " 1 0\n" << points.str() << comb.size() << indices.str() << "\n";
  std::ofstream(folder / "comb.ply") << "ply\nformat ascii 1.0\nelement vertex " << comb.size()
                                     << "\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
                                        "property list uchar int vertex_indices\nend_header\n"
                                     << points.str() << comb.size() << indices.str() << "\n";
  for (const char* name : {"comb.obj", "comb.off", "comb.ply"}) {
    INFO(name);
    const dg::Model model = dg::read_model(folder / name);
    require_tiles_comb(model.mesh.positions, model.mesh.triangles);
  }
}

TEST_CASE("polygon triangulation: corners a rounding's width off a straight edge leave no needle triangles",
          "[geometry]") {
  // A colonnade's floor: a strip 12 wide and 420 long along its outer edge x = 196.5, with six
  // tabs 30 wide reaching in to x = 154.7 under the columns, so the inner edge x = 184.5 is a run
  // of corners on one line. Its height drifts by 6e-5 along the strip in steps of 1e-5 (a file's
  // coordinates rounded), so in the polygon's plane those corners lie a rounding's width off
  // their line, on either side.
  std::vector<Vec3> positions;
  auto corner = [&](double x, double z) { positions.emplace_back(x, std::round((47.585 + 1.5e-7 * z) * 1e5) / 1e5, z); };
  corner(196.5, -230.0);
  corner(196.5, 190.0);
  for (double z : {74.0, 20.0, -34.0, -88.0, -142.0, -196.0}) {
    corner(184.5, z + 30.0);
    corner(154.7, z + 30.0);
    corner(154.7, z);
    corner(184.5, z);
  }
  std::vector<std::uint32_t> corners(positions.size());
  for (std::uint32_t i = 0; i < corners.size(); ++i) corners[i] = i;
  const std::vector<dg::Triangle> triangles = dg::triangulate_polygon(positions, corners);
  REQUIRE(triangles.size() == corners.size() - 2);
  for (const dg::Triangle& t : triangles) {
    const Vec3 a = positions[t[0]], b = positions[t[1]], c = positions[t[2]];
    INFO("triangle " << a.transpose() << " / " << b.transpose() << " / " << c.transpose());
    CHECK(height_over_longest_side(a, b, c) > 1e-3);  // no needle
  }
}

TEST_CASE("corpus: the Quaternius bank's notched floors and ceilings triangulate without needle triangles",
          "[geometry][corpus]") {
  // Its plinth top and colonnade ceiling are horizontal n-gons with runs of corners on straight
  // lines (one where each column notches them), some a rounding's width (1e-5) off the line:
  // clipped there, they left triangles 1e-7 to 1e-5 wide whose normals pointed anywhere and
  // whose edges counted as sharp along the whole colonnade. (Its stairs' sides hold polygons
  // that run out along a line and back, a spike of no area, whose triangles cannot but be thin.)
  const std::optional<std::filesystem::path> path = dg::test::corpus_file_if_present("meshes/arch-quaternius-bank/bank.obj");
  if (!path) return;
  const dg::Model model = dg::read_model(*path);
  const dg::TriangleMesh& mesh = model.mesh;
  const double extent = (mesh.bounds().max - mesh.bounds().min).maxCoeff();
  std::size_t horizontal = 0, needles = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    if (std::max({a.y(), b.y(), c.y()}) - std::min({a.y(), b.y(), c.y()}) > 1e-3) continue;
    ++horizontal;
    if (height_over_longest_side(a, b, c) < 1e-6 * extent) ++needles;
  }
  CHECK(horizontal > 500);
  CHECK(needles == 0);
}
