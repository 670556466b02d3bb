// clean_mesh / clean_point_cloud: exact weld, degenerate and unused-vertex removal, report counts.

#include "geometry/cleaning.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

using dg::CleaningReport;
using dg::PointCloud;
using dg::Triangle;
using dg::TriangleMesh;
using dg::Vec3;

namespace {

/// Unit cube as a triangle soup: 12 triangles, 36 positions (each corner repeated).
TriangleMesh cube_soup() {
  const Vec3 corners[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};
  TriangleMesh mesh;
  for (const auto& q : quads) {
    for (const auto& tri : {std::array<int, 3>{q[0], q[1], q[2]}, std::array<int, 3>{q[0], q[2], q[3]}}) {
      const auto first = static_cast<std::uint32_t>(mesh.positions.size());
      for (int corner : tri) mesh.positions.push_back(corners[corner]);
      mesh.triangles.push_back({first, first + 1, first + 2});
    }
  }
  return mesh;
}

}  // namespace

TEST_CASE("clean_mesh welds a triangle soup cube into a closed mesh", "[geometry][cleaning]") {
  TriangleMesh mesh = cube_soup();
  const CleaningReport report = dg::clean_mesh(mesh);
  CHECK(report.input_vertices == 36);
  CHECK(report.input_triangles == 12);
  CHECK(report.welded_vertices == 8);
  CHECK(report.vertices == 8);
  CHECK(report.triangles == 12);
  CHECK(report.degenerate_dropped == 0);
  CHECK(report.duplicate_triangles == 0);
  CHECK(report.non_manifold_edges == 0);
  CHECK(report.boundary_edges == 0);
  CHECK(report.inconsistent_edges == 0);
  CHECK(report.components == 1);
  CHECK(report.closed_and_oriented);
  CHECK(report.bounds.min == Vec3(0, 0, 0));
  CHECK(report.bounds.max == Vec3(1, 1, 1));
  // Vertices appear in order of first occurrence: the first triangle keeps indices 0, 1, 2.
  CHECK(mesh.triangles[0] == Triangle{0, 1, 2});
  CHECK(mesh.positions[1] == Vec3(0, 1, 0));
}

TEST_CASE("clean_mesh keeps the order of first occurrences and drops unused vertices", "[geometry][cleaning]") {
  TriangleMesh mesh;
  mesh.positions = {{5, 0, 0}, {9, 9, 9}, {0, 0, 0}, {0, 1, 0}, {5, 0, 0}, {0, 0, 0}, {1, 1, 1}};
  mesh.triangles = {{4, 3, 5}, {0, 6, 2}};
  const CleaningReport report = dg::clean_mesh(mesh);
  CHECK(report.welded_vertices == 5);  // (9,9,9) is unique but unused
  CHECK(report.vertices == 4);
  const std::vector<Vec3> expected = {{5, 0, 0}, {0, 0, 0}, {0, 1, 0}, {1, 1, 1}};
  CHECK(mesh.positions == expected);
  const std::vector<Triangle> triangles = {{0, 2, 1}, {0, 3, 1}};
  CHECK(mesh.triangles == triangles);
  CHECK(report.components == 1);  // the two triangles share two vertices
}

TEST_CASE("degenerate triangles are counted and dropped", "[geometry][cleaning]") {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                    {2, 0, 0},               // collinear with 0 and 1
                    {1, 0, 0},               // same position as 1: welded
                    {3, 1e-13, 0},           // sliver: height 1e-13 / 3 over a longest edge of 3
                    {3, 1e-6, 0}};           // thin, but a real triangle
  mesh.triangles = {{0, 1, 2},   // fine
                    {0, 1, 3},   // zero area, collinear
                    {0, 4, 2},   // same as the first after welding: a duplicate, kept
                    {1, 4, 2},   // repeated vertex after welding
                    {2, 2, 0},   // repeated index
                    {0, 5, 1},   // sliver below the tolerance
                    {0, 6, 1}};  // kept
  TriangleMesh kept = mesh;
  const CleaningReport report = dg::clean_mesh(mesh);
  CHECK(report.degenerate_dropped == 4);
  CHECK(report.triangles == 3);
  CHECK(report.duplicate_triangles == 1);
  CHECK(report.vertices == 4);  // 3 (= 2 0 0) and 5 are used only by dropped triangles

  dg::CleaningOptions count_only;
  count_only.drop_degenerate = false;
  const CleaningReport counted = dg::clean_mesh(kept, count_only);
  CHECK(counted.degenerate_dropped == 4);
  CHECK(counted.triangles == 7);
  CHECK(counted.vertices == 6);
}

TEST_CASE("back-to-back faces count as duplicates and are kept", "[geometry][cleaning]") {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {3, 5, 4}, {1, 2, 0}};
  const CleaningReport report = dg::clean_mesh(mesh);
  CHECK(report.triangles == 3);
  CHECK(report.duplicate_triangles == 2);
  CHECK(report.non_manifold_edges == 3);  // every edge is used three times
  CHECK(report.welded_vertices == 3);
}

TEST_CASE("three triangles on one edge give one non-manifold edge", "[geometry][cleaning]") {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const CleaningReport report = dg::clean_mesh(mesh);
  CHECK(report.non_manifold_edges == 1);
  CHECK(report.boundary_edges == 6);
  CHECK(report.duplicate_triangles == 0);
  CHECK_FALSE(report.closed_and_oriented);
}

TEST_CASE("the cleaning report as JSON", "[geometry][cleaning]") {
  TriangleMesh mesh = cube_soup();
  const nlohmann::json json = dg::to_json(dg::clean_mesh(mesh));
  CHECK(json.at("kind") == "mesh");
  CHECK(json.at("welded_vertices") == 8);
  CHECK(json.at("input_vertices") == 36);
  CHECK(json.at("closed_and_oriented") == true);
  CHECK(json.at("bounds").at("max") == nlohmann::json::array({1.0, 1.0, 1.0}));

  PointCloud empty;
  const nlohmann::json cloud = dg::to_json(dg::clean_point_cloud(empty));
  CHECK(cloud.at("kind") == "point_cloud");
  CHECK(cloud.at("points") == 0);
  CHECK(cloud.at("bounds").is_null());
}

TEST_CASE("clean_point_cloud drops repeats and invalid normals", "[geometry][cleaning]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  PointCloud cloud;
  cloud.positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {2, 0, 0}, {3, 0, 0}, {2, 0, 0}};
  cloud.normals = {{0, 0, 2}, {0, 1, 0}, {1, 0, 0}, {nan, 0, 0}, {0, 0, 0}, {0, 0, -1}};
  const CleaningReport report = dg::clean_point_cloud(cloud);
  CHECK(report.point_cloud);
  CHECK(report.input_vertices == 6);
  CHECK(report.invalid_normals_dropped == 2);
  CHECK(report.duplicate_points_dropped == 1);
  CHECK(report.vertices == 3);
  const std::vector<Vec3> positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  const std::vector<Vec3> normals = {{0, 0, 1}, {0, 1, 0}, {0, 0, -1}};  // the valid copy of (2,0,0) survives
  CHECK(cloud.positions == positions);
  CHECK(cloud.normals == normals);
  CHECK(report.bounds.max == Vec3(2, 0, 0));

  PointCloud bare;
  bare.positions = {{1, 2, 3}, {1, 2, 3}};
  const CleaningReport bare_report = dg::clean_point_cloud(bare);
  CHECK(bare_report.duplicate_points_dropped == 1);
  CHECK(bare.positions.size() == 1);
  CHECK(bare.normals.empty());
}
