// Writing meshes with materials: OBJ + MTL, PLY face colours, GLB primitives per material; and
// meshes without materials written exactly as before.

#include "geometry/model_io.h"

#include "support/cli_run.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstring>
#include <fstream>
#include <iterator>

using dg::Vec3;

namespace {

// Two unit squares side by side in z = 0; materials per triangle: brick, brick, glass, brick.
dg::TriangleMesh two_squares() {
  dg::TriangleMesh mesh;
  mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(2, 0, 0), Vec3(2, 1, 0)};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}};
  mesh.materials = {0, 0, 1, 0};
  return mesh;
}

const std::vector<dg::Material> kMaterials = {{"brick", Vec3(0.8, 0.2, 0.1)}, {"dark glass", Vec3(0.1, 0.3, 0.9)}};

std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("materials: OBJ names its MTL library and a material per run of triangles", "[geometry][io][materials]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-material-obj-test");
  dg::write_mesh_with_materials(folder / "wall.obj", two_squares(), kMaterials);
  CHECK(file_text(folder / "wall.obj") ==
        "# dockgrammar\nmtllib wall.mtl\n"
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n"
        "usemtl brick\nf 1 2 3\nf 1 3 4\nusemtl dark_glass\nf 2 5 6\nusemtl brick\nf 2 6 3\n");
  CHECK(file_text(folder / "wall.mtl") == "# dockgrammar\n\nnewmtl brick\nKd 0.8 0.2 0.1\n\nnewmtl dark_glass\nKd 0.1 0.3 0.9\n");
  // No temporary file is left behind.
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder)) ++files;
  CHECK(files == 2);
}

TEST_CASE("materials: MTL names are unique and hold no spaces", "[geometry][io][materials]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-material-names-test");
  dg::TriangleMesh mesh = two_squares();
  mesh.materials = {0, 1, 2, 3};
  dg::write_mesh_with_materials(folder / "m.obj", mesh,
                                {{"a", Vec3(1, 0, 0)}, {"", Vec3(0, 1, 0)}, {"a", Vec3(0, 0, 1)}, {"a 2", Vec3(1, 1, 1)}});
  const std::string obj = file_text(folder / "m.obj");
  CHECK(obj.find("usemtl a\nf 1 2 3\nusemtl material_1\nf 1 3 4\nusemtl a_2\nf 2 5 6\nusemtl a_2_3\nf 2 6 3\n") != std::string::npos);
  CHECK(file_text(folder / "m.mtl").find("newmtl a_2_3\nKd 1 1 1\n") != std::string::npos);
}

TEST_CASE("materials: PLY gives every face its material's colour", "[geometry][io][materials]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-material-ply-test");
  dg::write_mesh_with_materials(folder / "wall.ply", two_squares(), kMaterials);
  const std::string bytes = file_text(folder / "wall.ply");
  const std::string header_end =
      "element face 4\nproperty list uchar uint vertex_indices\nproperty uchar red\nproperty uchar green\n"
      "property uchar blue\nend_header\n";
  const std::size_t body = bytes.find(header_end);
  REQUIRE(body != std::string::npos);
  const std::size_t faces = body + header_end.size() + 6 * 3 * sizeof(double);
  REQUIRE(bytes.size() == faces + 4 * (1 + 3 * 4 + 3));
  const std::array<std::array<int, 3>, 2> rgb = {{{204, 51, 26}, {26, 77, 230}}};
  for (std::size_t t = 0; t < 4; ++t) {
    const std::size_t colour = faces + t * 16 + 13;
    for (std::size_t c = 0; c < 3; ++c)
      CHECK(static_cast<unsigned char>(bytes[colour + c]) == rgb[two_squares().materials[t]][c]);
  }
  // The file reads back as the same triangles.
  const dg::Model model = dg::read_model(folder / "wall.ply");
  CHECK(model.mesh.triangles == two_squares().triangles);
}

TEST_CASE("materials: GLB has one primitive per material with its base colour", "[geometry][io][materials]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-material-glb-test");
  dg::write_mesh_with_materials(folder / "wall.glb", two_squares(), kMaterials);
  const std::string bytes = file_text(folder / "wall.glb");
  REQUIRE(bytes.size() > 20);
  std::uint32_t json_length = 0;
  std::memcpy(&json_length, bytes.data() + 12, 4);
  const nlohmann::json document = nlohmann::json::parse(bytes.substr(20, json_length));
  const nlohmann::json& primitives = document["meshes"][0]["primitives"];
  REQUIRE(primitives.size() == 2);
  CHECK(primitives[0]["material"] == 0);
  CHECK(primitives[1]["material"] == 1);
  CHECK(document["accessors"][primitives[0]["indices"].get<int>()]["count"] == 9);
  CHECK(document["accessors"][primitives[1]["indices"].get<int>()]["count"] == 3);
  CHECK(document["materials"][1]["name"] == "dark glass");
  CHECK(document["materials"][1]["pbrMetallicRoughness"]["baseColorFactor"] == nlohmann::json({0.1, 0.3, 0.9, 1.0}));
  CHECK(dg::read_model(folder / "wall.glb").mesh.triangles.size() == 4);
}

TEST_CASE("materials: a mesh without materials is written exactly as write_mesh writes it", "[geometry][io][materials]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-material-none-test");
  dg::TriangleMesh plain = two_squares();
  plain.materials.clear();
  for (const std::string extension : {".obj", ".ply", ".glb"}) {
    INFO(extension);
    dg::write_mesh(folder / ("reference" + extension), plain);
    dg::write_mesh_with_materials(folder / ("no_indices" + extension), plain, kMaterials);
    dg::write_mesh_with_materials(folder / ("no_list" + extension), two_squares(), {});
    CHECK(file_text(folder / ("no_indices" + extension)) == file_text(folder / ("reference" + extension)));
    CHECK(file_text(folder / ("no_list" + extension)) == file_text(folder / ("reference" + extension)));
  }
  CHECK_FALSE(std::filesystem::exists(folder / "no_indices.mtl"));
  CHECK_FALSE(std::filesystem::exists(folder / "no_list.mtl"));
}

TEST_CASE("materials: opacity survives OBJ + MTL (d) and GLB (alpha, BLEND), and MTL Tr reads as 1 - Tr",
          "[geometry][io][materials]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-material-opacity-test");
  std::vector<dg::Material> materials = kMaterials;
  materials[1].opacity = 0.375;
  for (const char* file : {"wall.obj", "wall.glb"}) {
    INFO(file);
    dg::write_mesh_with_materials(folder / file, two_squares(), materials);
    const dg::Model back = dg::read_model(folder / file);
    REQUIRE(back.materials.size() == 2);
    CHECK(back.materials[0].opacity == 1.0);
    CHECK(back.materials[1].opacity == 0.375);
  }
  CHECK(file_text(folder / "wall.mtl").find("newmtl dark_glass\nKd 0.1 0.3 0.9\nd 0.375\n") != std::string::npos);
  CHECK(file_text(folder / "wall.mtl").find("newmtl brick\nKd 0.8 0.2 0.1\n\n") != std::string::npos);  // opaque: no d

  std::ofstream(folder / "tr.mtl") << "newmtl glass\nKd 0.2 0.2 0.2\nTr 0.75\n";
  std::ofstream(folder / "tr.obj") << "mtllib tr.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl glass\nf 1 2 3\n";
  CHECK(dg::read_model(folder / "tr.obj").materials.at(0).opacity == 0.25);
}
