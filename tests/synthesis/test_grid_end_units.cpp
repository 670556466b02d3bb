// Grid directions whose planes cannot reach every unit (r-erosion near the model's ends), and
// chains of planes across an extrusion, which repeats nothing.

#include "synthesis/grid_resize.h"

#include "assets/generator/asset.h"
#include "geometry/topology.h"
#include "grammar/grid_cut.h"
#include "support/mesh_distance.h"
#include "support/shapes.h"

#include <catch2/catch.hpp>

using dg::Vec3;

namespace {

struct Grids {
  double eps = 0.0;
  dg::TriangleMesh cleaned;
  std::vector<dg::GridRule> grids;
};

Grids grids_of(const dg::TriangleMesh& mesh, double r) {
  dg::Model model;
  model.mesh = mesh;
  dg::PrepareOptions options;
  options.r = r;
  const dg::PreparedModel prepared = dg::prepare_model(std::move(model), options);
  const dg::SymmetryResult symmetries = dg::detect_symmetries(prepared);
  return {prepared.surface.eps(), prepared.model.mesh, dg::find_grids(prepared, symmetries)};
}

dg::TriangleMesh stairs(int steps) { return dg::assets::make_asset("spiral_stairs", {{"steps", steps}}).mesh; }

constexpr double kToothPitch = 2.0;

// A bar along x from 0 to `length` (1 wide, 0.5 high) with `teeth` boxes (0.5 x 0.5 x 0.5) on
// top at x = 2, 4, ...
dg::TriangleMesh comb(int teeth, double length) {
  dg::TriangleMesh mesh = dg::test::make_box(Vec3(0, 0, 0), Vec3(length, 1, 0.5));
  for (int k = 1; k <= teeth; ++k)
    dg::test::append(mesh, dg::test::make_box(Vec3(k * kToothPitch, 0.25, 0.5), Vec3(k * kToothPitch + 0.5, 0.75, 1.0)));
  return mesh;
}

}  // namespace

TEST_CASE("spiral stairs analyzed at a coarse r still count every step, and resize to N steps gives stairs(N)",
          "[synthesis][grid]") {
  // The rise is 0.18: at r = 0.3 .. 0.6 the r-erosion leaves no area a plane may cross within
  // two to four steps of either end, so only 9, 8, 6 or 5 units lie between planes; the steps
  // beyond them are copies and count as units of the head and tail (at r = 0.5 only for planes
  // whose phase leaves whole steps at both ends).
  for (double r : {0.3, 0.4, 0.5, 0.6}) {
    const Grids g = grids_of(stairs(12), r);
    REQUIRE(g.grids.size() == 1);
    REQUIRE(g.grids[0].directions.size() == 1);
    const dg::GridDirection& d = g.grids[0].directions[0];
    CHECK(d.count == 12);  // ground truth: the generator's steps
    CHECK(dg::min_units(d) > 0);
    const std::vector<dg::GridPiece> pieces = dg::cut_grid_pieces(g.cleaned, g.grids[0], g.eps);
    for (int n : {12, 16, 5}) {
      if (n < dg::lowest_count(g.grids[0], 0)) continue;
      const dg::TriangleMesh resized = dg::resize_grid(g.grids[0], pieces, {n}, g.eps);
      const dg::TriangleMesh expected = stairs(n);
      CHECK(dg::is_closed_and_oriented(resized));
      CHECK(dg::test::hausdorff_distance(resized, expected) < g.eps);
      CHECK(resized.area() == Approx(expected.area()).epsilon(1e-3));
    }
  }
}

TEST_CASE("a comb whose bar runs on without teeth: the grid repeats the teeth, not slabs of the bare bar",
          "[synthesis][grid]") {
  // The bar slides onto itself under the tooth pitch everywhere; past the teeth a chain of planes
  // across the bare bar would hold about 11 units, more than between the teeth, yet it repeats
  // nothing. The grid is the teeth's: 5 units, one per tooth (the first and last tooth lie
  // within r of where the teeth end, beyond the planes, and count as copies).
  const Grids g = grids_of(comb(5, 40.0), 0.0);
  REQUIRE(g.grids.size() == 1);
  REQUIRE(g.grids[0].directions.size() == 1);
  const dg::GridDirection& d = g.grids[0].directions[0];
  CHECK((d.translation - Vec3(kToothPitch, 0, 0)).norm() < 1e-6);
  CHECK(d.count == 5);  // ground truth: the teeth
  const double first = d.cut, last = d.cut + d.count * d.pitch;
  CHECK(first > 0.0);
  CHECK(last < 5 * kToothPitch + 2.0);
  // Two more teeth: the bar grows by two pitches, the bare part moved along.
  const std::vector<dg::GridPiece> pieces = dg::cut_grid_pieces(g.cleaned, g.grids[0], g.eps);
  const dg::TriangleMesh resized = dg::resize_grid(g.grids[0], pieces, {7}, g.eps);
  const dg::TriangleMesh expected = comb(7, 40.0 + 2 * kToothPitch);
  CHECK(dg::test::hausdorff_distance(resized, expected) < g.eps);
  CHECK(resized.area() == Approx(expected.area()).epsilon(1e-3));
}
