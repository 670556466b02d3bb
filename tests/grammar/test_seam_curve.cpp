#include "grammar/seam_curve.h"

#include <catch2/catch.hpp>

namespace {

// Three flat fins on the edge from (0, 0, 0) to (0, 0, 1): triangle 0 reaches out along +x,
// triangle 1 along +y, triangle 2 along -x. Triangle 3 continues fin 0 beyond x = 1.
dg::TriangleMesh fins_on_one_edge() {
  dg::TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 1}};
  mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {2, 1, 5}};
  return mesh;
}

}  // namespace

TEST_CASE("seam curve: an edge that three triangles share is a seam where the piece meets any of the others",
          "[grammar][seam_curve]") {
  // Real assets have such edges (the Blendswap radiator's fins: 2,873 of them). The fins' edge
  // was no seam at all when only two-triangle edges counted, so a docker could leave a part
  // behind at one location and not at another with the same seam curve.
  const dg::TriangleMesh mesh = fins_on_one_edge();
  const dg::EdgeUsers users = dg::edge_users(mesh);

  // Fin 0 alone: the shared edge (fins 1 and 2 stay outside) and its edge to triangle 3.
  std::vector<char> inside{1, 0, 0, 0};
  std::vector<dg::Segment> seam = dg::seam_segments(mesh, users, {0}, inside);
  REQUIRE(seam.size() == 2);
  auto is_edge = [](const dg::Segment& s, const dg::Vec3& a, const dg::Vec3& b) {
    return (s[0] == a && s[1] == b) || (s[0] == b && s[1] == a);
  };
  CHECK((is_edge(seam[0], {0, 0, 0}, {0, 0, 1}) || is_edge(seam[1], {0, 0, 0}, {0, 0, 1})));
  CHECK((is_edge(seam[0], {1, 0, 0}, {0, 0, 1}) || is_edge(seam[1], {1, 0, 0}, {0, 0, 1})));

  // Fins 0 and 1 with triangle 3: fin 2 is still outside, so the shared edge stays a seam, once
  // for each inside triangle on it.
  inside = {1, 1, 0, 1};
  seam = dg::seam_segments(mesh, users, {0, 1, 3}, inside);
  CHECK(seam.size() == 2);
  for (const dg::Segment& s : seam) CHECK(is_edge(s, {0, 0, 0}, {0, 0, 1}));

  // Every triangle inside: no seam; the open border of the fins is the model's own.
  inside = {1, 1, 1, 1};
  CHECK(dg::seam_segments(mesh, users, {0, 1, 2, 3}, inside).empty());
}
