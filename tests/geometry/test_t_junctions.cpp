// Closing seams whose sides were triangulated differently (T-junctions), small holes welds leave,
// and open-edge flags.

#include "geometry/t_junctions.h"

#include "geometry/random.h"
#include "geometry/submesh.h"
#include "geometry/topology.h"
#include "support/shapes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

using dg::Vec3;

namespace {

// Two unit squares in the plane z = 0 meeting along x = 1: the left one as two triangles,
// the right one as three, with an extra vertex at (1, 0.5 + shift) on the shared side.
dg::TriangleMesh squares_with_t_junction(double shift) {
  dg::TriangleMesh mesh;
  mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),                          // left
                    Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(1, 1, 0), Vec3(1, 0.5 + shift, 0)};  // right
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 8}, {8, 5, 6}, {8, 6, 7}};
  return mesh;
}

}  // namespace

TEST_CASE("T-junction on a seam: the long edge is split and the seam closes", "[geometry][t_junctions]") {
  for (const bool with_flags : {false, true}) {
    CAPTURE(with_flags);
    dg::TriangleMesh mesh = squares_with_t_junction(1e-9);
    const std::vector<char> open = dg::open_edge_vertices(mesh);
    // Every vertex of these two open squares lies on an open edge.
    CHECK(std::count(open.begin(), open.end(), 1) == 9);
    // The left square is copy 0, the right one copy 1.
    std::vector<std::uint32_t> copies;
    dg::append_seam_labels(copies, std::vector<char>(open.begin(), open.begin() + 4), 0);
    dg::append_seam_labels(copies, std::vector<char>(open.begin() + 4, open.end()), 1);
    const std::size_t splits = dg::resolve_t_junctions(mesh, 1e-6, with_flags ? &copies : nullptr);
    CHECK(splits == 1);
    CHECK(mesh.positions.size() == 7);  // (1, 0) and (1, 1) welded
    CHECK(mesh.triangles.size() == 6);
    const dg::EdgeStatistics edges = dg::edge_statistics(mesh);
    CHECK(edges.boundary_edges == 6);  // only the outer rectangle stays open
    CHECK(edges.non_manifold_edges == 0);
    CHECK(edges.inconsistent_edges == 0);
    CHECK(mesh.area() == Approx(2.0));
  }
}

TEST_CASE("T-junction farther than the tolerance stays open", "[geometry][t_junctions]") {
  dg::TriangleMesh mesh = squares_with_t_junction(0.0);
  for (Vec3& p : mesh.positions)
    if (p.x() == 1.0 && p.y() == 0.5) p.x() += 1e-3;
  CHECK(dg::resolve_t_junctions(mesh, 1e-6) == 0);
  CHECK(dg::edge_statistics(mesh).boundary_edges == 9);
}

TEST_CASE("open edge vertices of a closed box and of a box without one face", "[geometry][t_junctions]") {
  dg::TriangleMesh box;
  box.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)};
  box.triangles = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                   {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  REQUIRE(dg::is_closed_and_oriented(box));
  const std::vector<char> closed = dg::open_edge_vertices(box);
  CHECK(std::count(closed.begin(), closed.end(), 1) == 0);
  box.triangles.erase(box.triangles.begin() + 2, box.triangles.begin() + 4);  // the top face z = 1
  CHECK(dg::open_edge_vertices(box) == std::vector<char>{0, 0, 0, 0, 1, 1, 1, 1});
}

TEST_CASE("a sliver whose third corner lies on its own open edge is dropped, not split", "[geometry][t_junctions]") {
  // The sliver a b c has c on its open edge a b; the triangle a c d beside it. Splitting a b at
  // c would give the parts a c c and c b c: triangles with a repeated corner.
  dg::TriangleMesh mesh;
  mesh.positions = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0)};
  enum : std::uint32_t { a, b, c, d };
  mesh.triangles = {{a, b, c}, {a, c, d}};
  mesh.materials = {0, 1};
  CHECK(dg::resolve_t_junctions(mesh, 1e-9) == 1);
  REQUIRE(mesh.triangles.size() == 1);
  CHECK(mesh.triangles[0] == dg::Triangle{a, c, d});
  CHECK(mesh.materials == std::vector<std::uint32_t>{1});
  CHECK(dg::edge_statistics(mesh).boundary_edges == 3);
}

namespace {

// A unit square [x0, x0 + 1] x [0, 1] in the plane z, fanned around its centre; with
// `midpoints`, its left and right sides have a vertex at y = 0.5.
dg::TriangleMesh square_part(double x0, double z, bool midpoints) {
  dg::TriangleMesh mesh;
  std::vector<Vec3> ring{Vec3(x0, 0, z), Vec3(x0 + 1, 0, z)};
  if (midpoints) ring.push_back(Vec3(x0 + 1, 0.5, z));
  ring.push_back(Vec3(x0 + 1, 1, z));
  ring.push_back(Vec3(x0, 1, z));
  if (midpoints) ring.push_back(Vec3(x0, 0.5, z));
  mesh.positions = ring;
  mesh.positions.push_back(Vec3(x0 + 0.5, 0.5, z));
  const auto centre = static_cast<std::uint32_t>(ring.size());
  for (std::uint32_t i = 0; i < centre; ++i) mesh.triangles.push_back({i, (i + 1) % centre, centre});
  return mesh;
}

void append(dg::TriangleMesh& to, const dg::TriangleMesh& part) {
  const auto base = static_cast<std::uint32_t>(to.positions.size());
  to.positions.insert(to.positions.end(), part.positions.begin(), part.positions.end());
  for (const dg::Triangle& t : part.triangles) to.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

}  // namespace

TEST_CASE("two touching parts of one copy stay apart when copies are welded", "[geometry][t_junctions]") {
  // Each copy holds two parts 2e-5 apart, closer than the weld tolerance 1e-4: a plain square
  // and one whose sides have a midpoint (lying on the plain square's sides within the tolerance).
  // Copy 1 is copy 0 moved by 1 along x; their seam is the plane x = 1.
  dg::TriangleMesh mesh;
  std::vector<std::uint32_t> copies;
  for (std::uint32_t copy = 0; copy < 2; ++copy) {
    for (const bool midpoints : {false, true}) {
      const dg::TriangleMesh part = square_part(copy, midpoints ? 2e-5 : 0.0, midpoints);
      append(mesh, part);
      dg::append_seam_labels(copies, dg::open_edge_vertices(part), copy);
    }
  }
  SECTION("labelled: each part closes with its own counterpart") {
    dg::resolve_t_junctions(mesh, 1e-4, &copies, 1e-9);
    const dg::EdgeStatistics edges = dg::edge_statistics(mesh);
    CHECK(edges.non_manifold_edges == 0);
    CHECK(edges.boundary_edges == 6 + 8);  // the outer sides of the two 2 x 1 rectangles
    CHECK(mesh.area() == Approx(4.0));
  }
  SECTION("unlabelled: the parts are welded to each other") {
    dg::resolve_t_junctions(mesh, 1e-4);
    CHECK(dg::edge_statistics(mesh).non_manifold_edges > 0);
  }
}

TEST_CASE("two parts touching face to face stay apart when copies are welded", "[geometry][t_junctions]") {
  // In each copy a seat's underside (facing -z) and a leg's top (facing +z, with midpoints on its
  // sides) lie in one plane, as touching boxes are modelled: their corners coincide exactly and
  // the top's midpoints lie exactly on the underside's sides, closer than any same-copy
  // tolerance, and so do those of the other copy. Copy 1 is copy 0 moved by 1 along x.
  dg::TriangleMesh mesh;
  std::vector<std::uint32_t> copies;
  for (std::uint32_t copy = 0; copy < 2; ++copy) {
    for (const bool top : {false, true}) {
      dg::TriangleMesh part = square_part(copy, 0.0, top);
      if (!top)
        for (dg::Triangle& t : part.triangles) std::swap(t[1], t[2]);
      append(mesh, part);
      dg::append_seam_labels(copies, dg::open_edge_vertices(part), copy);
    }
  }
  dg::resolve_t_junctions(mesh, 1e-4, &copies, 1e-9);
  const dg::EdgeStatistics edges = dg::edge_statistics(mesh);
  CHECK(edges.non_manifold_edges == 0);
  CHECK(edges.inconsistent_edges == 0);
  CHECK(edges.boundary_edges == 6 + 8);  // each side's copies join into one 2 x 1 rectangle
  CHECK(mesh.area() == Approx(4.0));
  std::size_t parts = 0;
  dg::triangle_components(mesh, &parts);
  CHECK(parts == 2);
}

TEST_CASE("labelled weld: duplicate vertices of one copy merge within the same-copy tolerance", "[geometry][t_junctions]") {
  // One copy's square split into two triangles with unshared corners (as unwelded files have),
  // and copy 1 beside it.
  dg::TriangleMesh mesh;
  mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
  append(mesh, square_part(1, 0, false));
  std::vector<std::uint32_t> copies(6, 0);
  copies.resize(mesh.positions.size(), 1);
  copies.back() = dg::kNotOnSeam;  // the centre of copy 1
  dg::resolve_t_junctions(mesh, 1e-4, &copies, 1e-9);
  const dg::EdgeStatistics edges = dg::edge_statistics(mesh);
  CHECK(edges.boundary_edges == 6);
  CHECK(edges.non_manifold_edges == 0);
  CHECK(mesh.positions.size() == 7);
}

TEST_CASE("close_triangular_holes fills a small hole of three open edges, oriented like its neighbours", "[geometry]") {
  dg::TriangleMesh box = dg::test::make_box(dg::Vec3(0, 0, 0), dg::Vec3(1, 1, 1));
  box.materials.assign(box.triangles.size(), 0);
  const dg::Triangle missing = box.triangles[5];
  box.triangles.erase(box.triangles.begin() + 5);
  box.materials.erase(box.materials.begin() + 5);
  REQUIRE_FALSE(dg::is_closed_and_oriented(box));
  // The hole's perimeter is 2 + sqrt(2) = 3.41: a smaller limit leaves it open.
  dg::TriangleMesh kept = box;
  CHECK(dg::close_triangular_holes(kept, 3.0) == 0);
  CHECK(kept.triangles.size() == 11);
  CHECK(dg::close_triangular_holes(box, 3.5) == 1);
  REQUIRE(box.triangles.size() == 12);
  CHECK(dg::is_closed_and_oriented(box));
  // The same corners as the removed triangle, in an order of the same orientation.
  std::array<std::uint32_t, 3> added{box.triangles.back()[0], box.triangles.back()[1], box.triangles.back()[2]};
  while (added[0] != missing[0]) std::rotate(added.begin(), added.begin() + 1, added.end());
  CHECK(added == std::array<std::uint32_t, 3>{missing[0], missing[1], missing[2]});
  CHECK(box.materials.size() == 12);
  // A closed mesh has no hole to close.
  CHECK(dg::close_triangular_holes(box, 10.0) == 0);
}

namespace {

// Two strips meeting along the x axis in the plane z = 0, for seams that misfit a little: copy
// 0 below, between its seam vertices at `lower_x` (on y = 0) and the corners (0, -1), (2, -1);
// copy 1 above, between its seam vertices `upper` (near y = 0) and the corners (0, 1), (2, 1).
// Both seams run from x = 0 to x = 2; each strip is a fan from its two far corners. `copies`
// gets the seam labels of both.
dg::TriangleMesh seam_strips(const std::vector<double>& lower_x, const std::vector<Vec3>& upper,
                             std::vector<std::uint32_t>& copies) {
  dg::TriangleMesh mesh;
  auto strip = [&](const std::vector<Vec3>& seam, double far_y, bool below) {
    const auto first = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), seam.begin(), seam.end());
    const auto left = static_cast<std::uint32_t>(mesh.positions.size()), right = left + 1;
    mesh.positions.push_back(Vec3(0, far_y, 0));
    mesh.positions.push_back(Vec3(2, far_y, 0));
    const auto middle = static_cast<std::uint32_t>(seam.size() / 2);
    auto add = [&](std::uint32_t corner, std::uint32_t a, std::uint32_t b) {  // counter-clockwise seen from +z
      mesh.triangles.push_back(below ? dg::Triangle{corner, b, a} : dg::Triangle{corner, a, b});
    };
    for (std::uint32_t i = 0; i < middle; ++i) add(left, first + i, first + i + 1);
    if (below)
      mesh.triangles.push_back({left, right, first + middle});
    else
      mesh.triangles.push_back({left, first + middle, right});
    for (auto i = middle; i + 1 < seam.size(); ++i) add(right, first + i, first + i + 1);
    std::vector<char> all(seam.size() + 2, 1);
    dg::append_seam_labels(copies, all, below ? 0 : 1);
  };
  std::vector<Vec3> lower;
  for (double x : lower_x) lower.push_back(Vec3(x, 0, 0));
  strip(lower, -1.0, true);
  strip(upper, 1.0, false);
  return mesh;
}

// Whether the two strips closed into one 2 x 2 rectangle: no non-manifold or inconsistent edge,
// and the open edges are its outer sides (their length about its perimeter).
bool closed_into_rectangle(const dg::TriangleMesh& mesh) {
  const dg::EdgeStatistics edges = dg::edge_statistics(mesh);
  double open_length = 0.0;
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const dg::Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
  for (const auto& [edge, count] : uses)
    if (count == 1) open_length += (mesh.positions[edge.first] - mesh.positions[edge.second]).norm();
  return edges.non_manifold_edges == 0 && edges.inconsistent_edges == 0 && std::abs(open_length - 8.0) < 0.1;
}

}  // namespace

TEST_CASE("labelled weld: a short seam edge next to a neighbour's vertex collapses instead of folding", "[geometry][t_junctions]") {
  // Copy 1's seam lies up to 0.0095 off copy 0's (the weld tolerance is 0.02) and holds two
  // vertices 0.003 apart (x = 1.0507 and 1.0537), both nearest to copy 0's vertex at x = 1.0621:
  // the first joins it; the second must too, or it folds back across the first.
  std::vector<std::uint32_t> copies;
  dg::TriangleMesh mesh = seam_strips({0, 0.3678, 0.4931, 0.96, 1.0621, 1.6475, 1.7225, 2},
                                      {Vec3(0, 0.0065, 0), Vec3(0.4044, 0.0034, 0), Vec3(0.9866, 0.0073, 0),
                                       Vec3(1.0064, 0.0082, 0), Vec3(1.0507, 0.0060, 0), Vec3(1.0537, 0.0089, 0),
                                       Vec3(1.2225, 0.0095, 0), Vec3(1.2883, 0.0069, 0), Vec3(1.6967, 0.0078, 0),
                                       Vec3(1.8858, 0.0038, 0), Vec3(2, 0.0034, 0)},
                                      copies);
  dg::resolve_t_junctions(mesh, 0.02, &copies, 3e-4);
  CHECK(closed_into_rectangle(mesh));
  CHECK(mesh.area() == Approx(4.0).margin(0.05));
}

TEST_CASE("labelled weld: seams that misfit by up to half the tolerance close", "[geometry][t_junctions]") {
  // Random seams: copy 0's vertices on y = 0, copy 1's 0.003 to 0.01 off it (the weld tolerance
  // is 0.02, twice the largest misfit, as for derived pieces), some of them in short runs next to
  // a vertex of copy 0, as cuts leave them.
  dg::Random random(7);
  int failures = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<double> lower_x{0.0, 2.0}, upper_x{0.0, 2.0};
    for (int n = 2 + static_cast<int>(random.uniform() * 5); n > 0; --n) lower_x.push_back(random.uniform(0.05, 1.95));
    for (int n = 2 + static_cast<int>(random.uniform() * 5); n > 0; --n) upper_x.push_back(random.uniform(0.05, 1.95));
    for (int n = static_cast<int>(random.uniform() * 4); n > 0; --n)
      upper_x.push_back(lower_x[2 + static_cast<std::size_t>(random.uniform() * static_cast<double>(lower_x.size() - 2))] +
                        random.uniform(-0.03, 0.03));
    std::sort(lower_x.begin(), lower_x.end());
    std::sort(upper_x.begin(), upper_x.end());
    std::vector<Vec3> upper;
    for (double x : upper_x) upper.push_back(Vec3(x, random.uniform(0.003, 0.01), 0));
    std::vector<std::uint32_t> copies;
    dg::TriangleMesh mesh = seam_strips(lower_x, upper, copies);
    dg::resolve_t_junctions(mesh, 0.02, &copies, 3e-4);
    failures += closed_into_rectangle(mesh) ? 0 : 1;
  }
  CHECK(failures == 0);
}

TEST_CASE("a sliver hanging off an edge of a closed box by its two open edges is dropped", "[geometry][t_junctions]") {
  // Left where a weld kept a seam vertex a hair apart from the corner it should have joined:
  // the box's edge gains a third user, and two open edges run to the stray vertex.
  dg::TriangleMesh box = dg::test::make_box(dg::Vec3(0, 0, 0), dg::Vec3(1, 1, 1));
  box.materials.assign(box.triangles.size(), 0);
  const dg::Triangle& first = box.triangles[0];
  const std::uint32_t a = first[0], b = first[1];
  const Vec3 stray = box.positions[b] + 1e-4 * (box.positions[a] - box.positions[b]) + Vec3(0, 0, 1e-7);
  auto with_sliver = [&](const Vec3& apex) {
    dg::TriangleMesh mesh = box;
    mesh.positions.push_back(apex);
    mesh.triangles.push_back({b, a, static_cast<std::uint32_t>(mesh.positions.size() - 1)});
    mesh.materials.push_back(0);
    return mesh;
  };
  dg::TriangleMesh near = with_sliver(stray);
  REQUIRE_FALSE(dg::is_closed_and_oriented(near));
  CHECK(dg::drop_hanging_slivers(near, 1e-3) == 1);
  CHECK(near.triangles.size() == 12);
  CHECK(near.materials.size() == 12);
  CHECK(dg::is_closed_and_oriented(dg::without_unused_vertices(near)));
  // A corner farther from the edge than the tolerance is a part of its own: it stays.
  dg::TriangleMesh far = with_sliver(box.positions[b] + Vec3(0.3, 0.3, 0.3));
  CHECK(dg::drop_hanging_slivers(far, 1e-3) == 0);
  CHECK(far.triangles.size() == 13);
}
