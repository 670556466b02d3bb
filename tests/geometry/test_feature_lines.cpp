#include "geometry/feature_lines.h"

#include "support/shapes.h"

#include <catch2/catch.hpp>

#include <cmath>

using dg::Vec3;

TEST_CASE("feature lines of a cube are its 12 edges", "[geometry]") {
  const double a = 2.5;
  const dg::TriangleMesh cube = dg::test::make_box(Vec3(0, 0, 0), Vec3(a, a, a));
  const auto edges = dg::find_feature_edges(cube);
  CHECK(edges.size() == 12);  // the face diagonals are flat
  for (const auto& e : edges) CHECK(e.dihedral_degrees == Approx(90.0));
  const dg::FeatureLines lines = dg::extract_feature_lines(cube, edges, a / 10.0);
  CHECK(lines.lines.size() == 12);
  CHECK(lines.total_length() == Approx(12 * a));
  // 11 samples per edge at spacing a/10, each with an orthonormal frame.
  CHECK(lines.samples.size() == 12 * 11);
  for (const auto& s : lines.samples) {
    CHECK(s.tangent.norm() == Approx(1.0));
    CHECK(std::abs(s.tangent.dot(s.normal)) < 1e-12);
    CHECK(s.binormal.isApprox(s.tangent.cross(s.normal)));
    CHECK(s.descriptor.dihedral_degrees == Approx(90.0));
    CHECK(s.descriptor.kind != dg::EdgeKind::boundary);
  }
}

TEST_CASE("boundary of an open square is one loop split at its corners", "[geometry]") {
  dg::TriangleMesh square;
  square.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  const auto edges = dg::find_feature_edges(square);
  CHECK(edges.size() == 4);
  const dg::FeatureLines lines = dg::extract_feature_lines(square, edges, 0.5);
  CHECK(lines.lines.size() == 4);
  CHECK(lines.total_length() == Approx(4.0));
  for (const auto& line : lines.lines) CHECK(line.kind == dg::EdgeKind::boundary);
}

TEST_CASE("a smooth sphere has no feature lines, a cylinder rim is a closed loop", "[geometry]") {
  const dg::TriangleMesh sphere = dg::test::make_sphere(Vec3::Zero(), 1.0, 30, 60);
  CHECK(dg::find_feature_edges(sphere).empty());

  // Open cylinder (a tube): two boundary loops, each turning 6 degrees per vertex.
  dg::TriangleMesh tube;
  const int segments = 60;
  for (int s = 0; s < segments; ++s) {
    const double phi = 2.0 * M_PI * s / segments;
    tube.positions.emplace_back(std::cos(phi), std::sin(phi), 0.0);
    tube.positions.emplace_back(std::cos(phi), std::sin(phi), 1.0);
  }
  for (std::uint32_t s = 0; s < segments; ++s) {
    const std::uint32_t n = (s + 1) % segments;
    tube.triangles.push_back({2 * s, 2 * n, 2 * n + 1});
    tube.triangles.push_back({2 * s, 2 * n + 1, 2 * s + 1});
  }
  const auto edges = dg::find_feature_edges(tube);
  CHECK(edges.size() == 2 * segments);
  const dg::FeatureLines lines = dg::extract_feature_lines(tube, edges, 0.1);
  REQUIRE(lines.lines.size() == 2);
  CHECK(lines.lines[0].closed);
  CHECK(lines.lines[1].closed);
  const double perimeter = 2.0 * segments * std::sin(M_PI / segments);
  CHECK(lines.total_length() == Approx(2.0 * perimeter));
  for (const auto& s : lines.samples) CHECK(s.descriptor.curvature == Approx(1.0).epsilon(0.01));
}

TEST_CASE("back-to-back duplicate faces do not create features", "[geometry]") {
  dg::TriangleMesh cube = dg::test::make_box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const std::size_t n = cube.triangles.size();
  for (std::size_t t = 0; t < n; ++t) {
    const dg::Triangle tri = cube.triangles[t];
    cube.triangles.push_back({tri[0], tri[2], tri[1]});
  }
  CHECK(dg::find_feature_edges(cube).size() == 12);
}
