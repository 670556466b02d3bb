// The files in assets/models/ are exactly what the generator writes now.

#include "assets/generator/committed_instances.h"
#include "support/cli_run.h"

#include <catch2/catch.hpp>
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
