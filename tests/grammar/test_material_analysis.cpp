// Analysing a model again with its interchangeable materials grouped: what `analyze` goes on
// with when geometry alone gives no grid.

#include "grammar/material_analysis.h"

#include "geometry/model_io.h"
#include "support/cli_run.h"
#include "support/material_models.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace {

// Wall stripes between glass stripes of two tints in no periodic order (the tints as one
// material repeat every two stripes), written as OBJ + MTL; its path.
std::filesystem::path tinted_stripes(const std::filesystem::path& folder) {
  std::vector<std::uint32_t> stripes;
  for (std::uint32_t tint : {1, 2, 2, 1, 1, 2, 1, 2, 2, 1}) stripes.insert(stripes.end(), {0u, tint});
  const dg::Model wall = dg::test::striped_wall(stripes, {"wall", "glass_green", "glass_blue"});
  dg::write_mesh_with_materials(folder / "stripes.obj", wall.mesh, wall.materials);
  return folder / "stripes.obj";
}

}  // namespace

TEST_CASE("materials grouped: a flat wall of stripes in random tints is analysed again with the tints as one",
          "[grammar][materials]") {
  const std::filesystem::path path = tinted_stripes(dg::test::fresh_folder("dockgrammar-material-analysis-test"));
  const dg::PreparedModel prepared = dg::prepare_model(path);
  const dg::SymmetryResult symmetries = dg::detect_symmetries(prepared);
  REQUIRE(dg::find_grids(prepared, symmetries).empty());  // flat: no repeat in geometry

  std::vector<std::string> stages;
  const dg::ProgressCallback progress = [&](std::string_view stage, double) {
    if (stages.empty() || stages.back() != stage) stages.emplace_back(stage);
    return true;
  };
  const std::optional<dg::GroupedMaterialAnalysis> grouped = dg::analyze_with_materials_grouped(path, prepared, {}, {}, 0, progress);
  REQUIRE(grouped);
  CHECK(grouped->hint.applied);
  REQUIRE(grouped->hint.groups.size() == 1);
  CHECK(grouped->hint.groups[0] == std::vector<std::string>{"glass_green", "glass_blue"});
  CHECK(grouped->prepared.materials_matched());
  CHECK(grouped->prepared.model.source_path == path.string());
  // One grid along the stripes, its pitch two stripes (a wall and a glass stripe), and its
  // counts are the hint's.
  REQUIRE(grouped->grids.size() == 1);
  REQUIRE(grouped->grids[0].directions.size() == 1);
  const dg::GridDirection& direction = grouped->grids[0].directions[0];
  CHECK(direction.pitch == Approx(2 * dg::test::kStripeHeight).epsilon(1e-9));
  CHECK(std::abs(direction.direction.y()) == Approx(1.0).epsilon(1e-9));
  CHECK(grouped->hint.grid_counts == std::vector<std::vector<int>>{dg::exemplar_counts(grouped->grids[0])});
  // Its grid is the one --same-material gives.
  const dg::PreparedModel same = dg::prepare_model(path, grouped->hint.options);
  const std::vector<dg::GridRule> same_grids = dg::find_grids(same, dg::detect_symmetries(same));
  REQUIRE(same_grids.size() == 1);
  CHECK(dg::exemplar_counts(same_grids[0]) == dg::exemplar_counts(grouped->grids[0]));
  // The second analysis names its stages apart from the first's.
  const auto hint_stage = std::find(stages.begin(), stages.end(), "material hint");
  REQUIRE(hint_stage != stages.end());
  CHECK(std::find(stages.begin(), stages.end(), "materials grouped: voxel surface") != stages.end());
  CHECK(std::find(stages.begin(), stages.end(), "materials grouped: grid rules") != stages.end());
  CHECK(std::all_of(hint_stage + 1, stages.end(), [](const std::string& s) { return s.starts_with("materials grouped: "); }));

  // Nothing when analysis already gave a grid or matched materials.
  CHECK_FALSE(dg::analyze_with_materials_grouped(path, prepared, {}, {}, 1));
  dg::PrepareOptions matched;
  matched.match_materials = true;
  CHECK_FALSE(dg::analyze_with_materials_grouped(path, prepared, matched, {}, 0));
}

TEST_CASE("materials grouped: stripes of materials that never repeat are not analysed again", "[grammar][materials]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-material-analysis-none-test");
  const dg::Model wall = dg::test::striped_wall({0, 1, 2, 1, 0, 2, 2}, {"red", "green", "blue"});
  dg::write_mesh_with_materials(folder / "plain.obj", wall.mesh, wall.materials);
  const dg::PreparedModel prepared = dg::prepare_model(folder / "plain.obj");
  CHECK_FALSE(dg::analyze_with_materials_grouped(folder / "plain.obj", prepared, {}, {}, 0));
}
