// Models far from their file's origin (survey coordinates): analyzed moved near the origin,
// with motions, grammar outputs and resized models back in the file's coordinates.

#include "geometry/model_io.h"
#include "geometry/prepared_model.h"
#include "geometry/submesh.h"
#include "support/cli_run.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fstream>
#include <string>

namespace {

// The generated fence moved by `offset`, written to `path`.
void write_moved_fence(const std::filesystem::path& path, const dg::Vec3& offset) {
  dg::RigidTransform move;
  move.translation = offset;
  const dg::Model fence = dg::read_model(std::string(DOCKGRAMMAR_SOURCE_DIR) + "/assets/models/fence_4.obj");
  dg::write_mesh(path, dg::transformed(fence.mesh, move));
}

nlohmann::json parsed(const dg::test::CliRun& run) {
  INFO(run.output);
  REQUIRE(run.status == 0);
  return nlohmann::json::parse(run.output);
}

}  // namespace

TEST_CASE("far origin: a box beyond the voxel grid's reach is moved from a round point near its middle", "[geometry]") {
  dg::BoundingBox near;
  near.add(dg::Vec3(-3, 0, 2));
  near.add(dg::Vec3(8, 1, 3));
  CHECK(dg::far_model_origin(near, 0.01).isZero());

  dg::BoundingBox far;
  far.add(dg::Vec3(10'000'020.5, -2'000'000.25, 7.0));
  far.add(dg::Vec3(10'000'031.5, -1'999'990.25, 9.0));
  CHECK_FALSE(dg::within_voxel_reach(far, 0.01));
  CHECK(dg::far_model_origin(far, 0.01) == dg::Vec3(10'000'000.0, -2'000'000.0, 0.0));
  // A voxel as large as the coordinates reaches them: nothing to move.
  CHECK(dg::far_model_origin(far, 100.0).isZero());
}

TEST_CASE("far origin: analyze, resize and verify a fence in survey coordinates as if it lay near the origin",
          "[tools][grammar]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-far-origin-test");
  const dg::Vec3 survey(412'345.67, 5'678'901.23, 310.5);
  const std::filesystem::path far_model = folder / "fence_far.obj";
  write_moved_fence(far_model, survey);
  auto run = [&](const std::string& arguments) { return dg::test::run_cli(arguments, folder); };

  // Before, the voxel grid refused the model (more than 2^20 voxels from the origin).
  const nlohmann::json far = parsed(run("analyze " + far_model.string() + " -q --json -o " + (folder / "far").string()));
  const dg::Vec3 origin(far["origin"][0].get<double>(), far["origin"][1].get<double>(), far["origin"][2].get<double>());
  CHECK(origin == dg::Vec3(412'400.0, 5'678'900.0, 300.0));
  // The same fence placed where the analysis saw it gives the same analysis.
  const std::filesystem::path local_model = folder / "fence_local.obj";
  write_moved_fence(local_model, survey - origin);
  const nlohmann::json local = parsed(run("analyze " + local_model.string() + " -q --json -o " + (folder / "local").string()));
  CHECK(local["origin"] == nlohmann::json::array({0.0, 0.0, 0.0}));
  for (const char* key : {"symmetries", "dockers", "operations", "productions"}) {
    CAPTURE(key);
    CHECK(far[key] == local[key]);
  }
  REQUIRE(far["nonterminals"].size() == local["nonterminals"].size());
  for (std::size_t n = 0; n < far["nonterminals"].size(); ++n)  // seam misfits differ by float rounding
    CHECK(far["nonterminals"][n]["sites"] == local["nonterminals"][n]["sites"]);
  REQUIRE(far["grids"].size() == 1);
  CHECK(far["grids"][0]["counts"] == nlohmann::json::array({4}));
  const nlohmann::json pitch = far["grids"][0]["transforms"][0];
  CHECK(pitch[0][3].get<double>() == Approx(2.0));
  CHECK(pitch[1][3].get<double>() == Approx(0.0).margin(1e-9));

  // Motions are reported in the file's coordinates: the half turn about the vertical passes
  // through the fence's middle, 412350.67 along x.
  const nlohmann::json symmetries = parsed(run("symmetry " + far_model.string() + " -q --json --top 1"));
  const nlohmann::json turn = symmetries["symmetries"][0]["matrix"];
  const dg::Vec3 middle = survey + dg::Vec3(5.0, 0.0, 0.0);
  const dg::Vec3 moved_middle(turn[0][0].get<double>() * middle.x() + turn[0][1].get<double>() * middle.y() +
                                  turn[0][2].get<double>() * middle.z() + turn[0][3].get<double>(),
                              turn[1][0].get<double>() * middle.x() + turn[1][1].get<double>() * middle.y() +
                                  turn[1][2].get<double>() * middle.z() + turn[1][3].get<double>(),
                              0.0);
  CHECK((moved_middle - dg::Vec3(middle.x(), middle.y(), 0.0)).norm() < 1e-6);
  // Its axis point and translation are given in the same coordinates as its matrix.
  const nlohmann::json& first = symmetries["symmetries"][0];
  CHECK(first["axis_point"][0].get<double>() == Approx(middle.x()).margin(1e-6));
  CHECK(first["axis_point"][1].get<double>() == Approx(middle.y()).margin(1e-6));
  for (int row = 0; row < 3; ++row) CHECK(first["translation"][row].get<double>() == Approx(turn[row][3].get<double>()));

  // Resized, the far grammar builds the local grammar's fence back at the survey location.
  const std::filesystem::path far_resized = folder / "far6.obj", local_resized = folder / "local6.obj";
  REQUIRE(run("resize " + (folder / "far" / "fence_far.grammar.json").string() + " --grid grid1=6 -q -o " +
              far_resized.string()).status == 0);
  REQUIRE(run("resize " + (folder / "local" / "fence_local.grammar.json").string() + " --grid grid1=6 -q -o " +
              local_resized.string()).status == 0);
  const dg::TriangleMesh far_mesh = dg::read_model(far_resized).mesh, local_mesh = dg::read_model(local_resized).mesh;
  REQUIRE(far_mesh.triangles.size() == local_mesh.triangles.size());
  REQUIRE(far_mesh.positions.size() == local_mesh.positions.size());
  double largest_gap = 0.0;
  for (std::size_t v = 0; v < far_mesh.positions.size(); ++v)
    largest_gap = std::max(largest_gap, (far_mesh.positions[v] - origin - local_mesh.positions[v]).norm());
  CHECK(largest_gap < 1e-6);
  CHECK(far_mesh.bounds().size().x() == Approx(14.2).epsilon(1e-6));  // two more bays of 2

  // verify moves both models near the origin as well (its voxel grid would refuse them too).
  const dg::test::CliRun verified = run("verify " + far_model.string() + " " + far_resized.string());
  INFO(verified.output);
  CHECK(verified.status == 0);
}
