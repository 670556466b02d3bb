// verify: closedness, self-intersections and r-similarity of a candidate against its exemplar.

#include "synthesis/verify.h"

#include "assets/generator/asset.h"
#include "geometry/errors.h"
#include "geometry/model_io.h"
#include "geometry/self_intersections.h"
#include "geometry/surface_sampling.h"
#include "support/shapes.h"
#include "synthesis/r_similarity_index.h"
#include "support/cli_run.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <sys/wait.h>
#include <tbb/global_control.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

using dg::Vec3;
namespace fs = std::filesystem;

namespace {

dg::Model facade_model(int columns, int rows) {
  dg::Model model;
  model.mesh = dg::assets::make_asset("facade", {{"columns", columns}, {"rows", rows}}).mesh;
  return model;
}

// facade(3, 4) with the window of column 1, row 1 (x in [4.9, 6.1], recess y in [0, 0.15],
// z in [7.9, 9.4]) scaled by `factor` about its centre.
dg::Model facade_with_scaled_window(double factor) {
  dg::Model model = facade_model(3, 4);
  const Vec3 lo(4.9, 0.0, 7.9), hi(6.1, 0.15, 9.4), centre = 0.5 * (lo + hi);
  int moved = 0;
  for (Vec3& p : model.mesh.positions)
    if ((p.array() >= lo.array() - 1e-9).all() && (p.array() <= hi.array() + 1e-9).all()) {
      p = centre + factor * (p - centre);
      ++moved;
    }
  REQUIRE(moved >= 8);
  return model;
}

// A scan-like cloud of `points` points drawn on the model's surface (with the triangles' normals).
dg::Model scan_of(const dg::Model& model, std::size_t points, std::uint64_t seed) {
  dg::Model cloud;
  cloud.cloud = dg::sample_surface(model.mesh, points, seed);
  return cloud;
}

struct Run {
  int status = -1;
  std::string output;
};

Run run_cli(const std::string& arguments, const fs::path& folder) {
  const fs::path log = folder / "cli.log";
  const std::string command = std::string(DOCKGRAMMAR_CLI) + " " + arguments + " > " + log.string() + " 2>&1";
  const int raw = std::system(command.c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, text.str()};
}

const dg::CheckResult& check(const dg::VerifyReport& report, const std::string& name) {
  for (const dg::CheckResult& c : report.checks)
    if (c.name == name) return c;
  FAIL("no check named " << name);
  return report.checks.front();
}

}  // namespace

TEST_CASE("verify: an exemplar is r-similar to itself", "[synthesis][verify]") {
  const dg::VerifyReport report = dg::verify_models(facade_model(3, 4), facade_model(3, 4));
  CHECK(report.pass);
  CHECK(report.candidate.closed);
  CHECK(report.candidate.oriented);
  CHECK(report.candidate.self_intersections == 0);
  CHECK(report.similarity.samples == 1000);
  CHECK(report.similarity.fraction == 1.0);
  CHECK(report.similarity.r == Approx(0.016 * 16.6));
}

TEST_CASE("verify: a larger facade is r-similar to the smaller exemplar", "[synthesis][verify]") {
  const dg::VerifyReport report = dg::verify_models(facade_model(3, 4), facade_model(5, 7));
  CHECK(report.pass);
  CHECK(report.similarity.fraction >= 0.995);
  for (const dg::CheckResult& c : report.checks) CHECK(c.pass);
}

TEST_CASE("verify: r-similarity does not depend on placement (a moved and turned copy)", "[synthesis][verify]") {
  dg::Model moved = facade_model(3, 4);
  const Eigen::AngleAxisd turn(1.1, Vec3(1, 2, 3).normalized());
  for (Vec3& p : moved.mesh.positions) p = turn * p + Vec3(3, 1, -2);
  const dg::VerifyReport report = dg::verify_models(facade_model(3, 4), std::move(moved));
  CHECK(report.pass);
  CHECK(report.similarity.fraction >= 0.995);
  CHECK(report.similarity.searched > 0);  // the identity fits nowhere: every motion was searched for
}

TEST_CASE("verify: the result does not depend on the thread count", "[synthesis][verify]") {
  dg::VerifyOptions options;
  options.similarity.samples = 300;
  const dg::VerifyReport all = dg::verify_models(facade_model(3, 4), facade_with_scaled_window(1.3), options);
  const auto one_thread = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, 1);
  const dg::VerifyReport one = dg::verify_models(facade_model(3, 4), facade_with_scaled_window(1.3), options);
  CHECK(all.similarity.similar == one.similarity.similar);
  CHECK(all.similarity.dissimilar_points == one.similarity.dissimilar_points);
}

TEST_CASE("verify: one window scaled by 1.3 loses the samples around it", "[synthesis][verify]") {
  const dg::VerifyReport report = dg::verify_models(facade_model(3, 4), facade_with_scaled_window(1.3));
  CHECK_FALSE(report.pass);
  CHECK_FALSE(check(report, "r_similarity").pass);
  CHECK(report.similarity.fraction < 0.995);
  REQUIRE_FALSE(report.similarity.dissimilar_points.empty());
  // Every dissimilar point lies within r of a triangle that the scaling moved.
  const dg::Model original = facade_model(3, 4), broken = facade_with_scaled_window(1.3);
  const double r = report.similarity.r;
  for (const Vec3& p : report.similarity.dissimilar_points) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t t = 0; t < broken.mesh.triangles.size(); ++t) {
      const auto [a, b, c] = broken.mesh.corners(t);
      const auto [a0, b0, c0] = original.mesh.corners(t);
      if (a != a0 || b != b0 || c != c0) nearest = std::min(nearest, (dg::closest_point_on_triangle(p, a, b, c) - p).norm());
    }
    CHECK(nearest <= r + 1e-9);
  }
}

TEST_CASE("verify: a removed triangle fails closedness", "[synthesis][verify]") {
  dg::Model holed = facade_model(3, 4);
  holed.mesh.triangles.erase(holed.mesh.triangles.begin() + 100);
  const dg::VerifyReport report = dg::verify_models(facade_model(3, 4), std::move(holed));
  CHECK_FALSE(report.pass);
  CHECK_FALSE(check(report, "closed").pass);
  CHECK_FALSE(report.candidate.closed);
  CHECK(report.candidate.boundary_edges == 3);
  CHECK(report.candidate.non_manifold_edges == 0);
  CHECK(check(report, "self_intersections").pass);
}

TEST_CASE("verify: overlapping boxes self-intersect", "[synthesis][verify]") {
  dg::TriangleMesh boxes = dg::test::make_box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  dg::test::append(boxes, dg::test::make_box(Vec3(0.5, 0.5, 0.5), Vec3(1.5, 1.5, 1.5)));
  const dg::SelfIntersections found = dg::find_self_intersections(boxes);
  CHECK(found.any);
  CHECK_FALSE(found.capped);
  CHECK_FALSE(found.non_manifold_input);
  // Each box crosses the other in 3 faces (6 triangles); each crossing triangle meets 2..4 others.
  CHECK(found.pairs.size() >= 12);
  for (const auto& [a, b] : found.pairs) CHECK((a < 12 && b >= 12));
  const dg::SelfIntersections capped = dg::find_self_intersections(boxes, {3});
  CHECK(capped.capped);
  CHECK(capped.pairs.size() == 3);
  CHECK_FALSE(dg::find_self_intersections(dg::test::make_box(Vec3(0, 0, 0), Vec3(1, 1, 1))).any);

  dg::Model exemplar, candidate;
  exemplar.mesh = dg::test::make_box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  candidate.mesh = boxes;
  const dg::VerifyReport report = dg::verify_models(std::move(exemplar), std::move(candidate));
  CHECK_FALSE(check(report, "self_intersections").pass);
  CHECK(report.candidate.self_intersections == found.pairs.size());
  CHECK(check(report, "closed").pass);
  CHECK_FALSE(report.pass);
}

TEST_CASE("verify: touching boxes sharing a vertex do not self-intersect", "[synthesis][verify]") {
  // Two boxes meeting at one corner (welded into one vertex): a non-manifold vertex.
  dg::TriangleMesh boxes = dg::test::make_box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  dg::test::append(boxes, dg::test::make_box(Vec3(1, 1, 1), Vec3(2, 2, 2)));
  dg::Model model;
  model.mesh = boxes;
  const dg::VerifyReport report = dg::verify_models(model, model);
  CHECK(report.pass);
  CHECK(report.similarity.fraction == 1.0);
}

TEST_CASE("verify CLI: exit 0 when valid, 1 when a check fails, 2 for bad input", "[synthesis][verify][cli]") {
  const fs::path folder = dg::test::fresh_folder("dockgrammar-verify-cli-test");
  dg::write_mesh(folder / "exemplar.obj", facade_model(3, 4).mesh);
  dg::write_mesh(folder / "large.ply", facade_model(5, 7).mesh);
  dg::write_mesh(folder / "broken.obj", facade_with_scaled_window(1.3).mesh);
  const std::string exemplar = (folder / "exemplar.obj").string();

  Run ok = run_cli("verify " + exemplar + " " + (folder / "large.ply").string() + " --json -q", folder);
  CHECK(ok.status == 0);
  const nlohmann::json json = nlohmann::json::parse(ok.output.substr(ok.output.find('{')));
  CHECK(json["pass"] == true);
  CHECK(json["closed"] == true);
  CHECK(json["oriented"] == true);
  CHECK(json["boundary_edges"] == 0);
  CHECK(json["non_manifold_edges"] == 0);
  CHECK(json["self_intersections"] == 0);
  CHECK(json["samples"] == 1000);
  CHECK(json["r_similar_fraction"].get<double>() >= 0.995);
  CHECK(json["r"].get<double>() == Approx(0.2656));
  CHECK(json["checks"]["r_similarity"]["pass"] == true);
  CHECK(json["timings_s"].contains("r-similarity"));

  Run broken = run_cli("verify " + exemplar + " " + (folder / "broken.obj").string() + " -q", folder);
  CHECK(broken.status == 1);
  CHECK(broken.output.find("FAIL r_similarity") != std::string::npos);
  CHECK(broken.output.find("PASS closed") != std::string::npos);

  Run radius = run_cli("verify " + exemplar + " " + exemplar + " -r 0.4 --json -q", folder);
  CHECK(radius.status == 0);
  CHECK(nlohmann::json::parse(radius.output.substr(radius.output.find('{')))["r"].get<double>() == Approx(0.4));

  Run missing = run_cli("verify " + exemplar + " " + (folder / "missing.obj").string(), folder);
  CHECK(missing.status == 2);
  CHECK(missing.output.find("missing.obj") != std::string::npos);
  std::ofstream(folder / "garbage.obj") << "v 1 2\nf 1 2 x\n";
  CHECK(run_cli("verify " + (folder / "garbage.obj").string() + " " + exemplar, folder).status == 2);
  CHECK(run_cli("verify " + exemplar, folder).status == 2);
  fs::remove_all(folder);
}

// Point clouds: about 4 points per voxel face (eps = 0.066) on the 3 x 4 facade.
TEST_CASE("verify: two independent scans of the facade are r-similar point clouds", "[synthesis][verify][cloud]") {
  const dg::VerifyReport report = dg::verify_models(scan_of(facade_model(3, 4), 200000, 1), scan_of(facade_model(3, 4), 200000, 2));
  CHECK(report.pass);
  CHECK(report.similarity.fraction >= 0.995);
  CHECK(report.candidate.point_cloud);
  CHECK(report.candidate.points == 200000);
  CHECK_FALSE(report.candidate.normals_estimated);
  REQUIRE(report.checks.size() == 1);
  CHECK(report.checks[0].name == "r_similarity");
}

TEST_CASE("verify: a scan of a larger facade is r-similar to the scan of the smaller", "[synthesis][verify][cloud]") {
  const dg::VerifyReport report = dg::verify_models(scan_of(facade_model(3, 4), 200000, 1), scan_of(facade_model(5, 7), 430000, 2));
  CHECK(report.pass);
  CHECK(report.similarity.fraction >= 0.995);
}

TEST_CASE("verify: a moved and turned scan without normals is r-similar", "[synthesis][verify][cloud]") {
  dg::Model moved = scan_of(facade_model(3, 4), 200000, 2);
  const Eigen::AngleAxisd turn(1.1, Vec3(1, 2, 3).normalized());
  for (Vec3& p : moved.cloud.positions) p = turn * p + Vec3(3, 1, -2);
  moved.cloud.normals.clear();
  const dg::VerifyReport report = dg::verify_models(scan_of(facade_model(3, 4), 200000, 1), std::move(moved));
  CHECK(report.candidate.normals_estimated);
  CHECK_FALSE(report.exemplar.normals_estimated);
  CHECK(report.pass);
  CHECK(report.similarity.fraction >= 0.995);
}

TEST_CASE("verify: a scan with one window scaled by 1.3 loses the samples around it", "[synthesis][verify][cloud]") {
  const dg::VerifyReport report =
      dg::verify_models(scan_of(facade_model(3, 4), 200000, 1), scan_of(facade_with_scaled_window(1.3), 200000, 2));
  CHECK_FALSE(report.pass);
  CHECK(report.similarity.fraction < 0.995);
  REQUIRE_FALSE(report.similarity.dissimilar_points.empty());
  // Every dissimilar point lies within r of the scaled window (x in [4.72, 6.28], z in [7.675, 9.625]).
  const double r = report.similarity.r;
  for (const Vec3& p : report.similarity.dissimilar_points) {
    CHECK(p.x() > 4.72 - r);
    CHECK(p.x() < 6.28 + r);
    CHECK(p.z() > 7.675 - r);
    CHECK(p.z() < 9.625 + r);
  }
}

TEST_CASE("verify: a point cloud against a mesh is a clear input error", "[synthesis][verify][cloud]") {
  CHECK_THROWS_AS(dg::verify_models(facade_model(3, 4), scan_of(facade_model(3, 4), 1000, 1)), dg::InputError);
  CHECK_THROWS_WITH(dg::verify_models(scan_of(facade_model(3, 4), 1000, 1), facade_model(3, 4)),
                    Catch::Contains("is a point cloud and") && Catch::Contains("two meshes or two point clouds"));
}

TEST_CASE("verify: scans with noise of 0.075 eps match within a tolerance widened to the noise", "[synthesis][verify][cloud]") {
  dg::Model a = scan_of(facade_model(3, 4), 200000, 1), b = scan_of(facade_model(3, 4), 200000, 2);
  const double eps = 0.2656 / 4.0;
  dg::add_noise(a.cloud, 0.075 * eps, 3);
  dg::add_noise(b.cloud, 0.075 * eps, 4);
  const dg::VerifyReport report = dg::verify_models(a, b);
  CHECK(report.similarity.tolerance > 0.25 * eps * 1.1);
  CHECK(report.similarity.tolerance < 0.5 * eps);
  CHECK(report.pass);
  // Still not so wide that a window scaled by 1.3 passes.
  dg::Model scaled = scan_of(facade_with_scaled_window(1.3), 200000, 2);
  dg::add_noise(scaled.cloud, 0.075 * eps, 4);
  CHECK_FALSE(dg::verify_models(a, scaled).pass);
}
