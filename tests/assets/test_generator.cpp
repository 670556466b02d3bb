// Generated assets: closed and outward, ground truth consistent with the geometry, counts and
// unit areas that make resizing exact, detail that keeps the shape.

#include "assets/generator/asset.h"
#include "geometry/errors.h"
#include "geometry/topology.h"
#include "tests/assets/asset_checks.h"

#include <catch2/catch.hpp>
#include <string>

using dg::assets::Asset;
using dg::assets::make_asset;
namespace t = dg::assets::test;

namespace {

/// The clean models (all but the damaged facade) at their default parameters.
std::vector<std::string> clean_names() {
  std::vector<std::string> names;
  for (const std::string& name : dg::assets::asset_names())
    if (name != "messy_facade") names.push_back(name);
  return names;
}

double relative_difference(double a, double b) { return std::abs(a - b) / std::max(std::abs(a), std::abs(b)); }

}  // namespace

TEST_CASE("every clean asset is one closed, outward, non-degenerate, self-intersection-free surface", "[assets]") {
  for (const std::string& name : clean_names()) {
    INFO(name);
    const Asset asset = make_asset(name, nlohmann::json::object());
    REQUIRE(asset.mesh.triangles.size() > 100);
    CHECK(dg::is_closed_and_oriented(asset.mesh));
    CHECK(t::signed_volume(asset.mesh) > 0.0);
    std::size_t components = 0;
    dg::triangle_components(asset.mesh, &components);
    CHECK(components == 1);
    const double scale = asset.mesh.bounds().diagonal();
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < asset.mesh.triangles.size(); ++i) smallest = std::min(smallest, asset.mesh.area_vector(i).norm());
    CHECK(smallest > 1e-8 * scale * scale);
    CHECK(t::self_intersections(asset.mesh) == 0);
  }
}

TEST_CASE("other parameters give sound models too", "[assets]") {
  const std::vector<std::pair<std::string, nlohmann::json>> cases = {
      {"fence", {{"n", 1}, {"pitch", 0.6}}},
      {"fence", {{"n", 2}, {"after_gate", 3}}},
      {"facade", {{"columns", 1}, {"rows", 1}, {"column_pitch", 1.7}, {"row_pitch", 2.8}}},
      {"shelf", {{"columns", 1}, {"rows", 2}, {"cell_width", 0.8}}},
      {"pipe_tree", {{"depth", 0}}},
      {"pipe_tree", {{"depth", 1}}},
      {"pipe_tree", {{"depth", 5}, {"span", 4.0}}},
      {"spiral_stairs", {{"steps", 30}, {"steps_per_turn", 8}, {"detail", 2}}},
      {"spiral_stairs", {{"steps", 2}, {"steps_per_turn", 3}}},
      {"gear", {{"teeth", 6}}},
      {"gear", {{"teeth", 31}, {"hole_ratio", 0.1}, {"detail", 2}}}};
  for (const auto& [name, params] : cases) {
    INFO(name << " " << params.dump());
    const Asset asset = make_asset(name, params);
    CHECK(dg::is_closed_and_oriented(asset.mesh));
    CHECK(t::signed_volume(asset.mesh) > 0.0);
    CHECK(t::self_intersections(asset.mesh) == 0);
    for (const nlohmann::json& rep : asset.ground_truth.at("repetitions")) {
      const auto count = rep.at("count").get<std::size_t>();
      CHECK(t::vertices_mapped_onto_vertices(asset.mesh, t::matrix_from_json(rep.at("transform"))) >=
            (count - 1) * rep.at("unit_vertices").get<std::size_t>());
    }
  }
}

TEST_CASE("the self-intersection check finds overlapping copies", "[assets]") {
  dg::TriangleMesh mesh = make_asset("gear", nlohmann::json::object()).mesh;
  REQUIRE(t::self_intersections(mesh) == 0);
  const std::size_t vertices = mesh.positions.size(), triangles = mesh.triangles.size();
  for (std::size_t v = 0; v < vertices; ++v) mesh.positions.push_back(mesh.positions[v] + dg::Vec3(0.01, 0.0, 0.005));
  for (std::size_t i = 0; i < triangles; ++i) {
    const dg::Triangle tri = mesh.triangles[i];
    mesh.triangles.push_back({tri[0] + static_cast<std::uint32_t>(vertices), tri[1] + static_cast<std::uint32_t>(vertices),
                              tri[2] + static_cast<std::uint32_t>(vertices)});
  }
  CHECK(t::self_intersections(mesh) > 0);
}

TEST_CASE("ground truth records the mesh's counts, area and bounding box", "[assets]") {
  for (const std::string& name : dg::assets::asset_names()) {
    INFO(name);
    const Asset asset = make_asset(name, nlohmann::json::object());
    const nlohmann::json& truth = asset.ground_truth;
    CHECK(truth.at("name") == asset.name);
    CHECK(truth.at("generator") == name);
    CHECK(truth.at("triangle_count").get<std::size_t>() == asset.mesh.triangles.size());
    CHECK(truth.at("vertex_count").get<std::size_t>() == asset.mesh.positions.size());
    CHECK(truth.at("surface_area").get<double>() == Approx(asset.mesh.area()).epsilon(1e-12));
    const dg::BoundingBox box = asset.mesh.bounds();
    for (int axis = 0; axis < 3; ++axis) {
      CHECK(truth["bounding_box"]["min"][static_cast<std::size_t>(axis)].get<double>() == box.min[axis]);
      CHECK(truth["bounding_box"]["max"][static_cast<std::size_t>(axis)].get<double>() == box.max[axis]);
    }
    CHECK(truth.at("parameters").contains("detail"));
    CHECK_FALSE(truth.at("repetitions").empty());
  }
}

TEST_CASE("each recorded repetition maps the units onto each other", "[assets]") {
  for (const std::string& name : clean_names()) {
    const Asset asset = make_asset(name, nlohmann::json::object());
    for (const nlohmann::json& rep : asset.ground_truth.at("repetitions")) {
      INFO(name << " " << rep.at("name").get<std::string>());
      const auto count = rep.at("count").get<std::size_t>();
      const auto unit_vertices = rep.at("unit_vertices").get<std::size_t>();
      REQUIRE(count >= 2);
      REQUIRE(unit_vertices > 0);
      CHECK(rep.at("unit_area").get<double>() > 0.0);
      const dg::Mat4 transform = t::matrix_from_json(rep.at("transform"));
      CHECK(t::vertices_mapped_onto_vertices(asset.mesh, transform) >= (count - 1) * unit_vertices);
      // The transform must really move things: the identity would pass the count trivially.
      CHECK((transform - dg::Mat4::Identity()).norm() > 1e-3);
    }
  }
}

TEST_CASE("rotation and screw repetitions are full turns of the right order", "[assets]") {
  const Asset gear = make_asset("gear", {{"teeth", 12}});
  const dg::Mat4 r = t::matrix_from_json(gear.ground_truth["repetitions"][0]["transform"]);
  dg::Mat4 power = dg::Mat4::Identity();
  for (int k = 0; k < 12; ++k) power = power * r;
  CHECK((power - dg::Mat4::Identity()).norm() < 1e-12);
  CHECK(t::vertices_mapped_onto_vertices(gear.mesh, r) == gear.mesh.positions.size());

  const Asset stairs = make_asset("spiral_stairs", {{"steps", 12}, {"steps_per_turn", 12}});
  const dg::Mat4 s = t::matrix_from_json(stairs.ground_truth["repetitions"][0]["transform"]);
  CHECK(s(2, 3) == Approx(0.18));
  CHECK(stairs.ground_truth["repetitions"][0]["kind"] == "screw");
}

TEST_CASE("fence(9) is fence(4) with exactly five more units", "[assets]") {
  const Asset small = make_asset("fence", {{"n", 4}});
  const Asset large = make_asset("fence", {{"n", 9}});
  const double unit = small.ground_truth["repetitions"][0]["unit_area"].get<double>();
  CHECK(relative_difference(large.mesh.area() - small.mesh.area(), 5 * unit) < 1e-9);
  CHECK(large.ground_truth["repetitions"][0]["count"] == 9);
  CHECK(large.ground_truth["repetitions"][0]["unit_area"].get<double>() == Approx(unit).epsilon(1e-12));
  // Bounding boxes differ by exactly five pitches along x.
  const double pitch = small.ground_truth["repetitions"][0]["pitch"]["vector"][0].get<double>();
  CHECK(large.mesh.bounds().size().x() - small.mesh.bounds().size().x() == Approx(5 * pitch).epsilon(1e-12));
  CHECK(large.mesh.bounds().size().z() == small.mesh.bounds().size().z());
}

TEST_CASE("a fence with a gate grows by whole units on either side of it", "[assets]") {
  const Asset small = make_asset("fence", {{"n", 3}, {"after_gate", 4}});
  const Asset larger = make_asset("fence", {{"n", 5}, {"after_gate", 6}});
  const nlohmann::json& reps = small.ground_truth["repetitions"];
  REQUIRE(reps.size() == 2);
  CHECK(reps[0]["count"] == 3);
  CHECK(reps[1]["count"] == 4);
  // Both stretches repeat the same unit (inner post and rails, mid-bay to mid-bay).
  const double unit = reps[0]["unit_area"].get<double>();
  CHECK(reps[1]["unit_area"].get<double>() == Approx(unit).epsilon(1e-12));
  CHECK(relative_difference(larger.mesh.area() - small.mesh.area(), 4 * unit) < 1e-9);
  CHECK(larger.mesh.bounds().size().x() - small.mesh.bounds().size().x() == Approx(4 * 2.0).epsilon(1e-12));
  // Without a gate the fence is the plain one.
  CHECK(make_asset("fence", {{"n", 3}, {"after_gate", 0}}).mesh.triangles == make_asset("fence", {{"n", 3}}).mesh.triangles);
  CHECK_THROWS_AS(make_asset("fence", {{"n", 3}, {"after_gate", -1}}), dg::InputError);
}

TEST_CASE("2-grids grow by whole columns, rows and cells", "[assets]") {
  // Area is bilinear in the counts: A(c, m) = a + b c + g m + d c m, where the recorded column
  // unit (at m rows) is b + d m, the row unit (at c columns) is g + d c and the cell is d.
  for (const std::string& name : {std::string("facade"), std::string("shelf")}) {
    INFO(name);
    const Asset small = make_asset(name, {{"columns", 3}, {"rows", 4}});
    const Asset large = make_asset(name, {{"columns", 5}, {"rows", 7}});
    const nlohmann::json& truth = small.ground_truth;
    const double column = truth["repetitions"][0]["unit_area"].get<double>();
    const double row = truth["repetitions"][1]["unit_area"].get<double>();
    const double cell = truth["grids"][0]["cell_area"].get<double>();
    const double expected = 2 * (column - 4 * cell) + 3 * (row - 3 * cell) + (5 * 7 - 3 * 4) * cell;
    CHECK(relative_difference(large.mesh.area() - small.mesh.area(), expected) < 1e-9);
    CHECK(truth["grids"][0]["counts"] == nlohmann::json({3, 4}));
    CHECK(large.ground_truth["grids"][0]["counts"] == nlohmann::json({5, 7}));
    CHECK(large.ground_truth["grids"][0]["cell_area"].get<double>() == Approx(cell).epsilon(1e-12));
    // The cell is a proper part of both slabs.
    CHECK(cell < column);
    CHECK(cell < row);
  }
}

TEST_CASE("detail multiplies triangles but keeps area and bounding box", "[assets]") {
  for (const std::string& name : dg::assets::asset_names()) {
    INFO(name);
    const Asset coarse = make_asset(name, nlohmann::json::object());
    const Asset fine = make_asset(name, {{"detail", 3}});
    CHECK(fine.mesh.triangles.size() >= 4 * coarse.mesh.triangles.size());
    if (name != "messy_facade") {
      CHECK(dg::is_closed_and_oriented(fine.mesh));
      CHECK(relative_difference(fine.mesh.area(), coarse.mesh.area()) < 1e-9);
      CHECK(relative_difference(t::signed_volume(fine.mesh), t::signed_volume(coarse.mesh)) < 1e-9);
    }
    const dg::BoundingBox a = coarse.mesh.bounds(), b = fine.mesh.bounds();
    CHECK((a.min - b.min).norm() < 1e-12);
    CHECK((a.max - b.max).norm() < 1e-12);
    // Repetitions keep their transforms and unit areas.
    const auto& reps_a = coarse.ground_truth["repetitions"];
    const auto& reps_b = fine.ground_truth["repetitions"];
    REQUIRE(reps_a.size() == reps_b.size());
    for (std::size_t i = 0; i < reps_a.size(); ++i) {
      CHECK(reps_a[i]["transform"] == reps_b[i]["transform"]);
      CHECK(reps_a[i]["count"] == reps_b[i]["count"]);
      CHECK(relative_difference(reps_a[i]["unit_area"].get<double>(), reps_b[i]["unit_area"].get<double>()) < 1e-9);
    }
  }
}

TEST_CASE("the repeated units of a detailed model still map onto each other", "[assets]") {
  for (const std::string& name : clean_names()) {
    INFO(name);
    const Asset asset = make_asset(name, {{"detail", 2}});
    for (const nlohmann::json& rep : asset.ground_truth.at("repetitions")) {
      const auto count = rep.at("count").get<std::size_t>();
      CHECK(t::vertices_mapped_onto_vertices(asset.mesh, t::matrix_from_json(rep.at("transform"))) >=
            (count - 1) * rep.at("unit_vertices").get<std::size_t>());
    }
  }
}

TEST_CASE("bad model names and parameters are input errors", "[assets]") {
  CHECK_THROWS_AS(make_asset("castle", nlohmann::json::object()), dg::InputError);
  CHECK_THROWS_AS(make_asset("fence", {{"posts", 3}}), dg::InputError);
  CHECK_THROWS_AS(make_asset("fence", {{"n", 0}}), dg::InputError);
  CHECK_THROWS_AS(make_asset("fence", {{"n", 2.5}}), dg::InputError);
  CHECK_THROWS_AS(make_asset("fence", {{"n", "four"}}), dg::InputError);
  CHECK_THROWS_AS(make_asset("facade", nlohmann::json::array()), dg::InputError);
  CHECK_THROWS_AS(make_asset("spiral_stairs", {{"rise", 0.04}}), dg::InputError);
  CHECK_THROWS_AS(make_asset("gear", {{"detail", 0}}), dg::InputError);
  CHECK_THROWS_WITH(make_asset("shelf", {{"colums", 5}}), Catch::Contains("colums"));
  CHECK(dg::assets::asset_names().size() == 7);
}
