// `--up x|y|z` on the commands that draw pictures: the camera's up axis follows the option,
// analyze stores it in the grammar file, and generate and resize default to the stored axis.

#include "geometry/model_io.h"
#include "geometry/png_reader.h"
#include "geometry/submesh.h"
#include "geometry/surface_sampling.h"
#include "support/cli_run.h"
#include "support/shapes.h"

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// Width and height (pixels) of the box around every pixel that is not the white background.
std::pair<int, int> occupied_size(const fs::path& png) {
  const dg::Image image = dg::read_png(png);
  int left = image.width, right = -1, top = image.height, bottom = -1;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const dg::Rgba8 p = image.at(x, y);
      if (p.r > 250 && p.g > 250 && p.b > 250) continue;
      left = std::min(left, x);
      right = std::max(right, x);
      top = std::min(top, y);
      bottom = std::max(bottom, y);
    }
  REQUIRE(right >= left);
  return {right - left + 1, bottom - top + 1};
}

bool taller_than_wide(const fs::path& png) {
  const auto [width, height] = occupied_size(png);
  return height > width;
}

// Height over width of the drawn model.
double aspect(const fs::path& png) {
  const auto [width, height] = occupied_size(png);
  return static_cast<double>(height) / width;
}

}  // namespace

// The spiral stairs stand along +z (2 x 2 wide, 3.16 tall) and are thinnest along x and y
// alike, so --up y lays them on their side; --up z, or their screw's axis without --up, stands
// them up.
TEST_CASE("up axis: --up z stands z-up stairs upright in analyze, generate, resize and symmetry pictures", "[tools][pictures]") {
  const fs::path folder = dg::test::fresh_folder("dockgrammar-up-axis-test");
  const std::string model = std::string(DOCKGRAMMAR_SOURCE_DIR) + "/assets/models/spiral_stairs_12.obj";

  // --up y: stairs lying down.
  REQUIRE(dg::test::run_cli("symmetry " + model + " -q --top 1 --up y -o " + (folder / "lying").string(), folder).status == 0);
  CHECK_FALSE(taller_than_wide(folder / "lying" / "symmetry_01.png"));
  // Without --up: the axis of the screw of 30 degrees that maps 90 % of the surface onto itself.
  REQUIRE(dg::test::run_cli("symmetry " + model + " -q --top 1 -o " + (folder / "turn").string(), folder).status == 0);
  CHECK(taller_than_wide(folder / "turn" / "symmetry_01.png"));
  const dg::test::AnalyzedModel guessed = dg::test::analyze_model("spiral_stairs_12", folder / "turn-analyze");
  REQUIRE(guessed.run.status == 0);
  {
    std::ifstream in(guessed.grammar);
    CHECK(nlohmann::json::parse(in).value("up", "") == "z");
    std::ifstream report(folder / "turn-analyze" / "spiral_stairs_12.report.md");
    const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
    CHECK(text.find("Up axis z: the axis of screw") != std::string::npos);
  }

  // With --up z: upright, and the axis is stored for generate.
  const dg::test::AnalyzedModel upright = dg::test::analyze_model("spiral_stairs_12", folder / "z", "--up z");
  REQUIRE(upright.run.status == 0);
  CHECK(taller_than_wide(folder / "z" / "spiral_stairs_12.grid1.png"));
  const std::string grammar = upright.grammar.string();
  {
    std::ifstream in(grammar);
    CHECK(nlohmann::json::parse(in).value("up", "") == "z");
  }
  REQUIRE(dg::test::run_cli("generate " + grammar + " --count 1 --pictures -q -o " + (folder / "stored").string(), folder).status == 0);
  CHECK(taller_than_wide(folder / "stored" / "variant_00000.png"));
  // An explicit --up wins over the stored axis: the same variant lies down (a variant's steps
  // can reach farther round than the exemplar's, so it is only flatter than upright).
  REQUIRE(dg::test::run_cli("generate " + grammar + " --count 1 --pictures --up y -q -o " + (folder / "y").string(), folder).status ==
          0);
  CHECK(aspect(folder / "y" / "variant_00000.png") < 0.9 * aspect(folder / "stored" / "variant_00000.png"));
  REQUIRE(dg::test::run_cli("resize " + grammar + " --grid grid1=16 --picture -o " + (folder / "stairs_16.obj").string(), folder)
              .status == 0);
  CHECK(taller_than_wide(folder / "stairs_16.png"));

  REQUIRE(dg::test::run_cli("symmetry " + model + " -q --top 1 --up z -o " + (folder / "symmetry").string(), folder).status == 0);
  CHECK(taller_than_wide(folder / "symmetry" / "symmetry_01.png"));

  // A bad axis is a usage error: exit status 2, and no picture.
  const dg::test::CliRun bad = dg::test::run_cli("symmetry " + model + " -q --up w -o " + (folder / "bad").string(), folder);
  CHECK(bad.status == 2);
  CHECK(bad.output.find("--up") != std::string::npos);
  CHECK_FALSE(fs::exists(folder / "bad"));
  CHECK(dg::test::run_cli("generate " + grammar + " --count 1 --pictures --up 2 -q -o " + (folder / "bad").string(), folder).status ==
        2);
  // A grammar file whose stored axis is not x, y or z is bad input.
  {
    std::ifstream in(grammar);
    nlohmann::json document = nlohmann::json::parse(in);
    document["up"] = "down";
    std::ofstream(folder / "z" / "broken.grammar.json") << document.dump(2);
  }
  const dg::test::CliRun broken =
      dg::test::run_cli("generate " + (folder / "z" / "broken.grammar.json").string() + " --count 1 -q -o " + (folder / "bad").string(),
                        folder);
  CHECK(broken.status == 2);
  CHECK(broken.output.find("\"up\"") != std::string::npos);
  fs::remove_all(folder);
}

// glTF defines +Y as up, so a .glb input is stored (and drawn) y-up even when its shape alone
// suggests z (the fence is thinnest along y); the same mesh as OBJ is read as z-up.
TEST_CASE("up axis: glTF input is y-up by its specification, OBJ input is guessed", "[tools][pictures]") {
  const fs::path folder = dg::test::fresh_folder("dockgrammar-up-axis-gltf-test");
  const dg::Model fence = dg::read_model(std::string(DOCKGRAMMAR_SOURCE_DIR) + "/assets/models/fence_4.obj");
  auto stored_up = [&](const std::string& file) {
    const fs::path output = folder / fs::path(file).extension().string().substr(1);
    dg::write_mesh(folder / file, fence.mesh);
    REQUIRE(dg::test::run_cli("analyze " + (folder / file).string() + " -q -o " + output.string(), folder).status == 0);
    std::ifstream in(output / "fence.grammar.json");
    return nlohmann::json::parse(in).value("up", "");
  };
  CHECK(stored_up("fence.glb") == "y");
  // As OBJ, the axis its posts turn about by quarter turns (61 % of the surface).
  CHECK(stored_up("fence.obj") == "z");
  fs::remove_all(folder);
}

// A low y-up bench (2 wide, 1 high, 4 long) is thinnest along y but no thin wall, so the guess
// keeps y up (the OBJ convention) and draws it lying, wider than tall; "thinnest along y means
// z up" stood such models (five of the corpus's buildings and furniture) on their side.
TEST_CASE("up axis: an OBJ thinnest along y but not a thin wall is guessed y-up", "[tools][pictures]") {
  const fs::path folder = dg::test::fresh_folder("dockgrammar-up-axis-bench-test");
  {
    std::ofstream bench(folder / "bench.obj");
    for (int corner = 0; corner < 8; ++corner)
      bench << "v " << 2 * (corner & 1) << ' ' << ((corner >> 1) & 1) << ' ' << 4 * ((corner >> 2) & 1) << '\n';
    bench << "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
  }
  REQUIRE(dg::test::run_cli("symmetry " + (folder / "bench.obj").string() + " -q --top 1 -o " + (folder / "guess").string(), folder).status == 0);
  CHECK_FALSE(taller_than_wide(folder / "guess" / "symmetry_01.png"));
  REQUIRE(dg::test::run_cli("symmetry " + (folder / "bench.obj").string() + " -q --top 1 --up z -o " + (folder / "z").string(), folder).status == 0);
  CHECK(taller_than_wide(folder / "z" / "symmetry_01.png"));
  fs::remove_all(folder);
}

// STL files are z-up by convention (CAD, 3D printing): the same bench as an STL file, with no
// turn or one-sided surface to go by, stands on z, tall and narrow, and analyze stores z.
TEST_CASE("up axis: an STL file without other cues is z-up by convention", "[tools][pictures]") {
  const fs::path folder = dg::test::fresh_folder("dockgrammar-up-axis-stl-test");
  const dg::TriangleMesh bench = dg::test::make_box(dg::Vec3(0, 0, 0), dg::Vec3(2, 1, 4));
  {
    std::ofstream stl(folder / "bench.stl");
    stl << "solid bench\n";
    for (std::size_t t = 0; t < bench.triangles.size(); ++t) {
      stl << " facet normal 0 0 0\n  outer loop\n";
      for (const dg::Vec3& p : bench.corners(t)) stl << "   vertex " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
      stl << "  endloop\n endfacet\n";
    }
    stl << "endsolid bench\n";
  }
  const std::string model = (folder / "bench.stl").string();
  REQUIRE(dg::test::run_cli("symmetry " + model + " -q --top 1 -o " + (folder / "pictures").string(), folder).status == 0);
  CHECK(taller_than_wide(folder / "pictures" / "symmetry_01.png"));
  const dg::test::CliRun run = dg::test::run_cli("analyze " + model + " -q --json -o " + (folder / "analysis").string(), folder);
  REQUIRE(run.status == 0);
  CHECK(nlohmann::json::parse(run.output)["up"] == "z");
  std::ifstream in(folder / "analysis" / "bench.report.md");
  const std::string report((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(report.find("Up axis z: STL files are z-up by convention") != std::string::npos);
  fs::remove_all(folder);
}

// glTF defines +Y as up: a variant written as .glb is turned so that the exemplar's up axis
// becomes +y, (x, y, z) -> (x, z, -y) for the z-up facade (a thin wall, guessed z-up), while
// OBJ keeps the model's axes; an explicit --up y keeps them in the .glb too.
TEST_CASE("up axis: generate and resize turn a z-up facade so that its up axis is glTF's +y", "[tools][pictures]") {
  const fs::path folder = dg::test::fresh_folder("dockgrammar-up-axis-glb-test");
  const dg::test::AnalyzedModel facade = dg::test::analyze_model("facade_3x4", folder);
  REQUIRE(facade.run.status == 0);
  const std::string grammar = facade.grammar.string();
  // Largest distance between a vertex of `glb` and that of `obj` mapped by `turn`.
  auto offset = [](const dg::TriangleMesh& glb, const dg::TriangleMesh& obj, auto turn) {
    REQUIRE(glb.positions.size() == obj.positions.size());
    double largest = 0.0;
    for (std::size_t v = 0; v < obj.positions.size(); ++v) largest = std::max(largest, (glb.positions[v] - turn(obj.positions[v])).norm());
    return largest;
  };
  auto z_to_y = [](const dg::Vec3& p) { return dg::Vec3(p.x(), p.z(), -p.y()); };
  auto same = [](const dg::Vec3& p) { return p; };
  constexpr double kFloat32 = 1e-5;  // glb stores float32

  for (const char* format : {"obj", "glb"})
    REQUIRE(dg::test::run_cli("generate " + grammar + " --count 1 --rules grid --format " + format + " -q -o " + (folder / format).string(),
                              folder)
                .status == 0);
  const dg::TriangleMesh obj = dg::read_model(folder / "obj" / "variant_00000.obj").mesh;
  CHECK(obj.bounds().size().z() > 5 * obj.bounds().size().y());  // the OBJ stands on z as the exemplar
  CHECK(offset(dg::read_model(folder / "glb" / "variant_00000.glb").mesh, obj, z_to_y) < kFloat32);

  for (const char* file : {"resized.obj", "resized.glb"})
    REQUIRE(dg::test::run_cli("resize " + grammar + " --grid grid1=4x5 -q -o " + (folder / file).string(), folder).status == 0);
  CHECK(offset(dg::read_model(folder / "resized.glb").mesh, dg::read_model(folder / "resized.obj").mesh, z_to_y) < kFloat32);

  REQUIRE(dg::test::run_cli("generate " + grammar + " --count 1 --rules grid --format glb --up y -q -o " + (folder / "y").string(), folder)
              .status == 0);
  CHECK(offset(dg::read_model(folder / "y" / "variant_00000.glb").mesh, obj, same) < kFloat32);
  fs::remove_all(folder);
}

// A scan of a tower (3 x 5 wide, 8 tall along z) from above and around: roof and walls, no
// floor, and no turn of 120 degrees or less to read up from. Up is the axis its points face
// along but never against (pictures follow the stored axis, see the stairs above); a scan
// without normals carries no side, and the pictures guess from its bounds.
TEST_CASE("up axis: a z-up scan seen from above, with normals, stands on z", "[tools][pictures]") {
  const fs::path folder = dg::test::fresh_folder("dockgrammar-up-axis-scan-test");
  const dg::TriangleMesh box = dg::test::make_box(dg::Vec3(0, 0, 0), dg::Vec3(3, 5, 8));
  std::vector<std::size_t> walls_and_roof;
  for (std::size_t t = 0; t < box.triangles.size(); ++t)
    if (box.area_vector(t).z() >= 0.0) walls_and_roof.push_back(t);
  dg::PointCloud scan = dg::sample_surface(dg::submesh(box, walls_and_roof), 20000, 5);
  dg::write_point_cloud(folder / "tower.ply", scan);
  scan.normals.clear();
  dg::write_point_cloud(folder / "bare.ply", scan);

  const dg::test::CliRun analyzed = dg::test::run_cli("analyze " + (folder / "tower.ply").string() + " -q --json -o " + (folder / "a").string(), folder);
  REQUIRE(analyzed.status == 0);
  CHECK(nlohmann::json::parse(analyzed.output).value("up", "") == "z");
  {
    std::ifstream report(folder / "a" / "tower.report.md");
    const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
    CHECK(text.find("Up axis z: 10.") != std::string::npos);  // 15 of 143 units^2 face +z
  }

  const dg::test::CliRun bare = dg::test::run_cli("analyze " + (folder / "bare.ply").string() + " -q --json -o " + (folder / "b").string(), folder);
  REQUIRE(bare.status == 0);
  CHECK(nlohmann::json::parse(bare.output)["up"].is_null());
  fs::remove_all(folder);
}
