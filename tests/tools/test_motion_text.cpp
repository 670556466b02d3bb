// How `symmetry` and `analyze` print fitted motions: the detector's rounding noise (an axis
// component of 1e-8, an axis point 1e-17 off the origin) prints as 0, so a rotation about the z
// axis through the origin reads as one.

#include "assets/generator/asset.h"
#include "geometry/model_io.h"
#include "support/cli_run.h"

#include <catch2/catch.hpp>

#include <cctype>
#include <string>

namespace {

// Whether `text` holds a number in exponent form such as 7.1316e-18.
bool has_exponent(const std::string& text) {
  for (std::size_t at = text.find("e-"); at != std::string::npos; at = text.find("e-", at + 1))
    if (at > 0 && std::isdigit(static_cast<unsigned char>(text[at - 1]))) return true;
  return false;
}

}  // namespace

TEST_CASE("symmetry: a gear's rotations read as about (0, 0, 1) through (0, 0, 0), without rounding noise",
          "[tools][symmetry]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-motion-text");
  const std::filesystem::path model = folder / "gear.obj";
  dg::write_mesh(model, dg::assets::make_asset("gear", {{"teeth", 12}}).mesh);
  const dg::test::CliRun run = dg::test::run_cli("symmetry " + model.string() + " -q", folder);
  INFO(run.output);
  REQUIRE(run.status == 0);
  CHECK(run.output.find("30.000 deg about (0, 0, 1) through (0, 0, 0)") != std::string::npos);
  CHECK_FALSE(has_exponent(run.output));
}
