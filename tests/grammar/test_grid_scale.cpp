// Analysis does not depend on the model's units: a fence drawn in kilometres (or as a tiny part
// in metres) gives the same grid as in metres, scaled.

#include "grammar/grid_rules.h"

#include "assets/generator/asset.h"

#include <catch2/catch.hpp>

#include <cmath>

TEST_CASE("fence(4) scaled by 1e-5 and 1e3: the same 1-grid with the pitch scaled", "[grammar][grid]") {
  for (double scale : {1e-5, 1e3}) {
    dg::Model model;
    model.mesh = dg::assets::make_asset("fence", {{"n", 4}}).mesh;
    for (dg::Vec3& p : model.mesh.positions) p *= scale;
    const dg::PreparedModel prepared = dg::prepare_model(std::move(model));
    const std::vector<dg::GridRule> grids = dg::find_grids(prepared, dg::detect_symmetries(prepared));
    INFO("scale " << scale << ", eps " << prepared.surface.eps());
    REQUIRE(grids.size() == 1);
    REQUIRE(grids[0].directions.size() == 1);
    CHECK(grids[0].directions[0].count == 4);
    CHECK(std::abs(grids[0].directions[0].pitch - 2.0 * scale) <= 1e-6 * scale);
  }
}
