// Joining needlessly split fragments again (re-triangulation of labelled regions).

#include "geometry/fragment_merge.h"

#include "geometry/topology.h"
#include "geometry/zone_cut.h"

#include <catch2/catch.hpp>

#include <algorithm>

using dg::Vec3;

namespace {

// The unit square in z = 0 (two triangles) cut along x = 0.1 .. 0.9 and y = 0.1 .. 0.9.
dg::ZoneCut diced_square() {
  dg::TriangleMesh square;
  square.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  dg::PlaneFamily x{Vec3::UnitX(), {}}, y{Vec3::UnitY(), {}};
  for (int k = 1; k <= 9; ++k) x.offsets.push_back(0.1 * k), y.offsets.push_back(0.1 * k);
  return dg::cut_zone(square, {1, 1}, {x, y}, 1e-9);
}

std::vector<char> corners_pinned(const dg::TriangleMesh& mesh) {
  std::vector<char> pinned(mesh.positions.size(), 0);
  std::fill(pinned.begin(), pinned.begin() + 4, 1);
  return pinned;
}

Vec3 centroid(const dg::TriangleMesh& mesh, std::size_t t) {
  const auto [a, b, c] = mesh.corners(t);
  return (a + b + c) / 3.0;
}

}  // namespace

TEST_CASE("fragment merge: a diced square keeps only its label border", "[geometry][fragment_merge]") {
  const dg::ZoneCut cut = diced_square();
  REQUIRE(cut.mesh.triangles.size() > 150);
  std::vector<std::uint32_t> label(cut.mesh.triangles.size());
  for (std::size_t t = 0; t < label.size(); ++t) label[t] = centroid(cut.mesh, t).x() < 0.5 ? 0 : 1;
  const dg::MergedFragments merged = dg::merge_fragments(cut.mesh, cut.origin, label, corners_pinned(cut.mesh));
  // Kept vertices: the 40 on the open outline (every 0.1) and, inside it, those on the label
  // border x = 0.5: 9 where the y planes cross it and 4 where diagonals of the first cut's
  // fragments do; a triangulation with them has 2 * 13 + 40 - 2 = 64 triangles.
  CHECK(merged.mesh.triangles.size() == 64);
  CHECK(merged.mesh.area() == Approx(1.0).epsilon(1e-12));
  for (std::size_t t = 0; t < merged.mesh.triangles.size(); ++t) {
    const Vec3 c = centroid(merged.mesh, t);
    CHECK((c.x() < 0.5) == (label[merged.representative[t]] == 0));  // on its label's side
    CHECK(merged.mesh.area_vector(t).z() > 0.0);                       // orientation kept
  }
  // Conforming: only the square's outline is open, in its 40 pieces.
  const dg::EdgeStatistics edges = dg::edge_statistics(merged.mesh);
  CHECK(edges.non_manifold_edges == 0);
  CHECK(edges.boundary_edges == 40);
}

TEST_CASE("fragment merge: one label and straightened open borders give back the two triangles", "[geometry][fragment_merge]") {
  const dg::ZoneCut cut = diced_square();
  const std::vector<std::uint32_t> label(cut.mesh.triangles.size(), 0);
  const dg::MergedFragments merged = dg::merge_fragments(cut.mesh, cut.origin, label, corners_pinned(cut.mesh), {.straighten_open_borders = true});
  CHECK(merged.mesh.triangles.size() == 2);
  CHECK(merged.mesh.area() == Approx(1.0).epsilon(1e-12));
  // Without straightening, the vertices on the open outline stay.
  const dg::MergedFragments kept = dg::merge_fragments(cut.mesh, cut.origin, label, corners_pinned(cut.mesh));
  CHECK(kept.mesh.triangles.size() > 2);
  CHECK(kept.mesh.area() == Approx(1.0).epsilon(1e-12));
}

TEST_CASE("fragment merge: straightened label borders keep only the vertices where borders turn or meet", "[geometry][fragment_merge]") {
  const dg::ZoneCut cut = diced_square();
  std::vector<std::uint32_t> label(cut.mesh.triangles.size());
  for (std::size_t t = 0; t < label.size(); ++t) label[t] = centroid(cut.mesh, t).x() < 0.5 ? 0 : 1;
  const dg::MergedFragments merged = dg::merge_fragments(cut.mesh, cut.origin, label, corners_pinned(cut.mesh), {.straighten_label_borders = true});
  // Inside the open outline (40 vertices, every 0.1) only (0.5, 0.5) stays, where the label
  // border x = 0.5 crosses the square's diagonal: 2 * 1 + 40 - 2 = 40 triangles.
  CHECK(merged.mesh.triangles.size() == 40);
  CHECK(merged.mesh.area() == Approx(1.0).epsilon(1e-12));
  for (std::size_t t = 0; t < merged.mesh.triangles.size(); ++t) {
    const Vec3 c = centroid(merged.mesh, t);
    CHECK((c.x() < 0.5) == (label[merged.representative[t]] == 0));
    CHECK(merged.mesh.area_vector(t).z() > 0.0);
  }
  const dg::EdgeStatistics edges = dg::edge_statistics(merged.mesh);
  CHECK(edges.non_manifold_edges == 0);
  CHECK(edges.boundary_edges == 40);
}

TEST_CASE("fragment merge: border vertices a cut moved by up to moved_distance still go", "[geometry][fragment_merge]") {
  // The y planes sit 4e-7 above the x planes' crossings with the square's diagonal, so the cut
  // snaps those crossings onto them (tolerance 1e-6): 2.8e-7 off the diagonal, the border
  // between the square's two triangles.
  dg::TriangleMesh square;
  square.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  dg::PlaneFamily x{Vec3::UnitX(), {}}, y{Vec3::UnitY(), {}};
  for (int k = 1; k <= 9; ++k) x.offsets.push_back(0.1 * k), y.offsets.push_back(0.1 * k + 4e-7);
  const dg::ZoneCut cut = dg::cut_zone(square, {1, 1}, {x, y}, 1e-6);
  const std::vector<std::uint32_t> label(cut.mesh.triangles.size(), 0);
  const std::vector<char> pinned = corners_pinned(cut.mesh);
  const dg::MergedFragments exact = dg::merge_fragments(cut.mesh, cut.origin, label, pinned, {.straighten_open_borders = true});
  CHECK(exact.mesh.triangles.size() > 100);  // the bent diagonal changes the area: fragments stay
  const dg::MergedFragments merged =
      dg::merge_fragments(cut.mesh, cut.origin, label, pinned, {.straighten_open_borders = true, .moved_distance = 1e-6});
  CHECK(merged.mesh.triangles.size() == 2);
  CHECK(merged.mesh.area() == Approx(cut.mesh.area()).epsilon(1e-6));
}

TEST_CASE("fragment merge: a region that keeps its fragments keeps their border vertices in its neighbours too",
          "[geometry][fragment_merge]") {
  dg::ZoneCut cut = diced_square();
  std::vector<std::uint32_t> label(cut.mesh.triangles.size());
  for (std::size_t t = 0; t < label.size(); ++t) label[t] = centroid(cut.mesh, t).x() < 0.5 ? 0 : 1;
  // Lifting the cut vertex at (0.8, 0.6) out of the plane makes the re-triangulation of its region
  // (the right half below the diagonal, without that vertex) change its area, so that region keeps
  // its fragments, and with them the vertices on x = 0.5 the left half would drop from its border.
  std::size_t lifted = cut.mesh.positions.size();
  for (std::size_t v = 0; v < cut.mesh.positions.size(); ++v)
    if ((cut.mesh.positions[v] - Vec3(0.8, 0.6, 0)).norm() < 1e-9) lifted = v;
  REQUIRE(lifted < cut.mesh.positions.size());
  cut.mesh.positions[lifted].z() = 1e-2;
  const dg::MergedFragments merged =
      dg::merge_fragments(cut.mesh, cut.origin, label, corners_pinned(cut.mesh), {.straighten_label_borders = true});
  const bool lifted_kept = std::any_of(merged.mesh.triangles.begin(), merged.mesh.triangles.end(), [&](const dg::Triangle& t) {
    return std::find(t.begin(), t.end(), static_cast<std::uint32_t>(lifted)) != t.end();
  });
  CHECK(lifted_kept);  // its region kept its fragments
  CHECK(merged.mesh.area() == Approx(cut.mesh.area()).epsilon(1e-12));
  // Conforming: no T-junction on x = 0.5, only the square's outline is open.
  const dg::EdgeStatistics edges = dg::edge_statistics(merged.mesh);
  CHECK(edges.non_manifold_edges == 0);
  CHECK(edges.boundary_edges == 40);
}

namespace {

// `layers` (each a list of triangles on the unit square's four corners, z = 0) diced like
// diced_square, then merged with one label and straightened open borders.
dg::MergedFragments merge_diced_layers(const std::vector<std::vector<dg::Triangle>>& layers) {
  dg::TriangleMesh square;
  square.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  for (const auto& layer : layers) square.triangles.insert(square.triangles.end(), layer.begin(), layer.end());
  dg::PlaneFamily x{Vec3::UnitX(), {}}, y{Vec3::UnitY(), {}};
  for (int k = 1; k <= 9; ++k) x.offsets.push_back(0.1 * k), y.offsets.push_back(0.1 * k);
  const dg::ZoneCut cut = dg::cut_zone(square, std::vector<char>(square.triangles.size(), 1), {x, y}, 1e-9);
  const std::vector<std::uint32_t> label(cut.mesh.triangles.size(), 0);
  return dg::merge_fragments(cut.mesh, cut.origin, label, corners_pinned(cut.mesh), {.straighten_open_borders = true});
}

// Each triangle's corners, sorted, in sorted order.
std::vector<dg::Triangle> vertex_sets(const dg::TriangleMesh& mesh) {
  std::vector<dg::Triangle> sets;
  for (dg::Triangle t : mesh.triangles) {
    std::sort(t.begin(), t.end());
    sets.push_back(t);
  }
  std::sort(sets.begin(), sets.end());
  return sets;
}

}  // namespace

TEST_CASE("fragment merge: a triangle held twice, cut alike in both copies, is one triangle again in each",
          "[geometry][fragment_merge]") {
  // Every cut edge inside the triangle has four users, two per copy.
  for (const bool turned : {false, true}) {
    const dg::Triangle copy = turned ? dg::Triangle{0, 2, 1} : dg::Triangle{0, 1, 2};
    const dg::MergedFragments merged = merge_diced_layers({{{0, 1, 2}}, {copy}});
    REQUIRE(merged.mesh.triangles.size() == 2);
    CHECK(vertex_sets(merged.mesh) == std::vector<dg::Triangle>{{0, 1, 2}, {0, 1, 2}});
    CHECK(merged.mesh.area() == Approx(1.0).epsilon(1e-12));
    const double facing = merged.mesh.area_vector(0).z() * merged.mesh.area_vector(1).z();
    CHECK((facing < 0.0) == turned);  // each copy keeps its own facing
  }
}

TEST_CASE("fragment merge: a square drawn twice along other diagonals merges in both layers", "[geometry][fragment_merge]") {
  // The two layers share the cuts' vertices; a new edge of one layer may be an edge of the
  // other's fragments (same plane), which must not keep the fragments.
  const dg::MergedFragments merged = merge_diced_layers({{{0, 1, 2}, {0, 2, 3}}, {{0, 1, 3}, {1, 2, 3}}});
  CHECK(merged.mesh.area() == Approx(2.0).epsilon(1e-12));
  CHECK(merged.mesh.triangles.size() == 4);  // each layer its two triangles again
}

TEST_CASE("fragment merge: a piece of two faces back to back keeps the corners of its outline", "[geometry][fragment_merge]") {
  // A part resting on another, both cut: a piece holds the square [1, 2]^2 of each, facing up
  // (fragments fanned about (1.5, 1.5), of one input triangle) and facing down (fanned about
  // (1.4, 1.6), of another), sharing the outline's corners and edge midpoints. Each outline edge
  // is used once by each facing (as an edge between two input triangles would be), but it is
  // where each face ends, and the outline turns at the square's corners.
  dg::TriangleMesh piece;
  piece.positions = {Vec3(1, 1, 0), Vec3(1.5, 1, 0), Vec3(2, 1, 0),   Vec3(2, 1.5, 0),  Vec3(2, 2, 0),
                     Vec3(1.5, 2, 0), Vec3(1, 2, 0), Vec3(1, 1.5, 0), Vec3(1.5, 1.5, 0), Vec3(1.4, 1.6, 0)};
  std::vector<std::uint32_t> origin;
  for (std::uint32_t i = 0; i < 8; ++i) {
    piece.triangles.push_back({i, (i + 1) % 8, 8}), origin.push_back(0);
    piece.triangles.push_back({(i + 1) % 8, i, 9}), origin.push_back(1);
  }
  const std::vector<std::uint32_t> label(origin.size(), 0);
  const std::vector<char> pinned(piece.positions.size(), 0);
  for (const bool straightened : {false, true}) {
    const dg::MergedFragments merged = dg::merge_fragments(piece, origin, label, pinned, {.straighten_open_borders = straightened});
    // Each face re-triangulated from its outline alone: the 8 vertices, or its 4 corners when
    // open borders are straightened.
    CHECK(merged.mesh.triangles.size() == (straightened ? 4u : 12u));
    dg::TriangleMesh up, down;  // the two faces apart
    up.positions = down.positions = merged.mesh.positions;
    for (std::size_t t = 0; t < merged.mesh.triangles.size(); ++t) {
      for (std::uint32_t v : merged.mesh.triangles[t]) CHECK(v < 8);
      CHECK((merged.mesh.area_vector(t).z() > 0.0) == (origin[merged.representative[t]] == 0));  // facing kept
      (origin[merged.representative[t]] == 0 ? up : down).triangles.push_back(merged.mesh.triangles[t]);
    }
    for (const dg::TriangleMesh* face : {&up, &down}) {
      CHECK(face->area() == Approx(1.0).epsilon(1e-12));
      const dg::EdgeStatistics edges = dg::edge_statistics(*face);
      CHECK(edges.non_manifold_edges == 0);
      CHECK(edges.boundary_edges == (straightened ? 4u : 8u));  // the outline, conforming with the other face's
    }
  }
}
