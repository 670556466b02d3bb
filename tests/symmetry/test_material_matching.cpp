// Matching materials: a symmetry must map each material onto a material of its class, judged
// cell by cell. Stripes three voxels tall are the hard case: every cell lies within one voxel of
// a stripe of the other material, so looking around the image cell is not enough.

#include "geometry/errors.h"
#include "geometry/material_classes.h"
#include "geometry/prepared_model.h"
#include "symmetry/symmetric_region.h"

#include "support/cell_symmetry.h"
#include "support/material_models.h"

#include <catch2/catch.hpp>

using dg::Vec3;

namespace {

// Fraction of the surface cells that the slide by t maps onto the same material and back.
double symmetric_fraction(const dg::PreparedModel& prepared, const Vec3& t) {
  return dg::test::symmetric_fraction(prepared, dg::RigidTransform{dg::Mat3::Identity(), t});
}

// Voxels of 0.5: each stripe of 1.5 is three voxels tall.
dg::PrepareOptions striped_options() {
  dg::PrepareOptions options;
  options.r = 2.0;
  options.eps = 0.5;
  options.match_materials = true;
  return options;
}

}  // namespace

TEST_CASE("striped wall: a slide by one stripe maps no stripe's inside onto its own material", "[symmetry][materials]") {
  std::vector<std::uint32_t> stripes;
  for (int i = 0; i < 20; ++i) stripes.push_back(static_cast<std::uint32_t>(i % 2));
  const dg::PreparedModel prepared = dg::prepare_model(dg::test::striped_wall(stripes, {"wall", "glass"}), striped_options());
  // One stripe maps wall onto glass: only the cells on a border (holding both) can match.
  const double by_one = symmetric_fraction(prepared, Vec3(0, dg::test::kStripeHeight, 0));
  CHECK(by_one < 0.5);
  // Two stripes repeat the pattern: all but the two stripes slid off the top.
  const double by_two = symmetric_fraction(prepared, Vec3(0, 2 * dg::test::kStripeHeight, 0));
  CHECK(by_two > 0.8);
  // Geometry alone: every slide within the wall is a symmetry.
  dg::PrepareOptions geometric = striped_options();
  geometric.match_materials = false;
  const dg::PreparedModel plain = dg::prepare_model(dg::test::striped_wall(stripes, {"wall", "glass"}), geometric);
  CHECK(symmetric_fraction(plain, Vec3(0, dg::test::kStripeHeight, 0)) > 0.85);
}

TEST_CASE("striped wall: glass stripes of two tints repeat when the tints are one material class", "[symmetry][materials]") {
  // Wall (0) between glass stripes tinted green (1) or blue (2) in no periodic order.
  const std::uint32_t glass[] = {1, 2, 2, 1, 1, 2, 1, 2, 2, 1};
  std::vector<std::uint32_t> stripes;
  for (std::uint32_t tint : glass) stripes.insert(stripes.end(), {0u, tint});
  const std::vector<std::string> names = {"wall", "glass_green", "glass_blue"};
  const Vec3 pitch(0, 2 * dg::test::kStripeHeight, 0);

  const dg::PreparedModel tinted = dg::prepare_model(dg::test::striped_wall(stripes, names), striped_options());
  dg::PrepareOptions grouped_options = striped_options();
  grouped_options.match_materials = false;  // implied by the group
  grouped_options.same_materials = {"glass_*"};
  const dg::PreparedModel grouped = dg::prepare_model(dg::test::striped_wall(stripes, names), grouped_options);
  CHECK(grouped.materials_matched());
  // 6 of the 9 glass stripes that slide onto glass change tint, so a third of the cells fail.
  CHECK(symmetric_fraction(tinted, pitch) < 0.7);
  CHECK(symmetric_fraction(grouped, pitch) > 0.8);
  // One stripe still maps glass onto wall.
  CHECK(symmetric_fraction(grouped, Vec3(0, dg::test::kStripeHeight, 0)) < 0.5);
}

TEST_CASE("material classes: '*' patterns, groups and clear errors", "[geometry][materials]") {
  CHECK(dg::matches_material_pattern("glas1", "glas*"));
  CHECK(dg::matches_material_pattern("glas", "glas*"));
  CHECK(dg::matches_material_pattern("jalousie2", "*lousie*"));
  CHECK(dg::matches_material_pattern("a_b_c", "a*c"));
  CHECK(dg::matches_material_pattern("beton", "beton"));
  CHECK_FALSE(dg::matches_material_pattern("beton", "beto"));
  CHECK_FALSE(dg::matches_material_pattern("Glas1", "glas*"));
  CHECK_FALSE(dg::matches_material_pattern("weiss", "glas*"));

  const std::vector<dg::Material> materials = {{"glas1"}, {"beton"}, {"glas2"}, {"jalousie1"}, {"weiss"}};
  CHECK(dg::material_classes(materials, {}) == std::vector<std::uint32_t>{0, 1, 2, 3, 4});
  CHECK(dg::material_classes(materials, {"glas*, jalousie1"}) == std::vector<std::uint32_t>{0, 1, 0, 0, 4});
  CHECK(dg::material_classes(materials, {"weiss,beton", "glas2,glas1"}) == std::vector<std::uint32_t>{0, 1, 0, 3, 1});
  CHECK_THROWS_WITH(dg::material_classes(materials, {"glas*,jalousie"}),
                    Catch::Contains("no material matches 'jalousie'") && Catch::Contains("glas1, beton, glas2"));
  CHECK_THROWS_WITH(dg::material_classes(materials, {"glas*", "glas1,weiss"}),
                    Catch::Contains("'glas1' is in two --same-material groups"));
  CHECK_THROWS_AS(dg::material_classes(materials, {" , "}), dg::InputError);
  CHECK_THROWS_WITH(dg::material_classes({}, {"glas*"}), Catch::Contains("(the model's materials: none)"));
}
