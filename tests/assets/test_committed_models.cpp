// The files in assets/models/ are exactly what the generator writes now.

#include "assets/generator/committed_instances.h"
#include "geometry/model_io.h"
#include "support/cli_run.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("committed asset files equal freshly generated ones", "[assets]") {
  const std::filesystem::path models = std::filesystem::path(DOCKGRAMMAR_SOURCE_DIR) / "assets" / "models";
  const std::filesystem::path scratch = dg::test::fresh_folder("dockgrammar-assets-test");
  for (const dg::assets::Instance& instance : dg::assets::committed_instances()) {
    INFO(instance.stem);
    const dg::assets::Asset asset = dg::assets::make_asset(instance.model, instance.params);
    CHECK(asset.name == instance.stem);
    const std::filesystem::path fresh = scratch / (instance.stem + ".obj");
    dg::assets::write_asset_files(asset, fresh);
    for (const char* extension : {".obj", ".json"}) {
      const std::filesystem::path committed = models / (instance.stem + extension);
      REQUIRE(std::filesystem::exists(committed));
      CHECK(std::filesystem::file_size(committed) < 200 * 1024);
      CHECK(file_bytes(committed) == file_bytes(std::filesystem::path(fresh).replace_extension(extension)));
    }
  }
}

TEST_CASE("an asset written as .glb stands in glTF's y-up frame and analyze finds its grid without --up", "[assets][tools]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-assets-glb-test");
  const dg::assets::Asset asset = dg::assets::make_asset("facade", {{"columns", 3}, {"rows", 4}});
  dg::assets::write_asset_files(asset, folder / "facade.glb");
  dg::BoundingBox box, z_up;
  for (const dg::Vec3& p : dg::read_model(folder / "facade.glb").mesh.positions) box.add(p);
  for (const dg::Vec3& p : asset.mesh.positions) z_up.add(p);
  // (x, y, z) -> (x, z, -y), within float rounding.
  CHECK(std::abs(box.min.x() - z_up.min.x()) < 1e-5);
  CHECK(std::abs(box.max.y() - z_up.max.z()) < 1e-5);
  CHECK(std::abs(box.min.y() - z_up.min.z()) < 1e-5);
  CHECK(std::abs(box.min.z() + z_up.max.y()) < 1e-5);
  const nlohmann::json truth = nlohmann::json::parse(file_bytes(folder / "facade.json"));
  CHECK(truth.contains("file_frame"));
  CHECK(truth["up"] == "z");  // the values stay in the generator's frame

  const dg::test::CliRun analyzed = dg::test::run_cli("analyze " + (folder / "facade.glb").string() + " -q --json -o " + (folder / "out").string(), folder);
  REQUIRE(analyzed.status == 0);
  const nlohmann::json summary = nlohmann::json::parse(analyzed.output);
  REQUIRE(summary["grids"].size() == 1);
  std::vector<int> counts = summary["grids"][0]["counts"].get<std::vector<int>>();
  std::sort(counts.begin(), counts.end());
  CHECK(counts == std::vector<int>{3, 4});
  // Rows climb glTF's +y now.
  bool rows_along_y = false;
  for (const nlohmann::json& transform : summary["grids"][0]["transforms"])
    rows_along_y |= std::abs(transform[1][3].get<double>()) > 1.0;  // rows of a 4x4: [1][3] is t.y
  CHECK(rows_along_y);
}
