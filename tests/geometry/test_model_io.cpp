// Reading and writing models: every format, round trips, and clear errors for bad files.

#include "geometry/cleaning.h"
#include "geometry/errors.h"
#include "geometry/model_io.h"
#include "support/cli_run.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace fs = std::filesystem;
using dg::InputError;
using dg::Model;
using dg::TriangleMesh;
using dg::Vec3;

namespace {

/// Fresh, empty folder for one test case's files (one per case, so cases may run in parallel).
fs::path test_folder(const std::string& name) { return dg::test::fresh_folder("dockgrammar-io-" + name); }

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

const Vec3 cube_corners[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
/// Outward counter-clockwise quads of the unit cube, 1-based like OBJ.
const int cube_quads[6][4] = {{1, 4, 3, 2}, {5, 6, 7, 8}, {1, 2, 6, 5}, {3, 4, 8, 7}, {1, 5, 8, 4}, {2, 3, 7, 6}};

/// The unit cube as the readers give it: quads fan-triangulated (a b c), (a c d).
TriangleMesh cube_mesh() {
  TriangleMesh mesh;
  mesh.positions.assign(std::begin(cube_corners), std::end(cube_corners));
  for (const auto& q : cube_quads) {
    const auto a = static_cast<std::uint32_t>(q[0] - 1), b = static_cast<std::uint32_t>(q[1] - 1),
               c = static_cast<std::uint32_t>(q[2] - 1), d = static_cast<std::uint32_t>(q[3] - 1);
    mesh.triangles.push_back({a, b, c});
    mesh.triangles.push_back({a, c, d});
  }
  return mesh;
}

std::string cube_obj() {
  std::string text = "# cube\nmtllib cube.mtl\no cube\n";
  for (const Vec3& p : cube_corners) {
    text += "v " + std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) + "\n";
  }
  text += "usemtl stone\ng sides\ns 1\n";
  for (const auto& q : cube_quads) {
    text += "f " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) + " " +
            std::to_string(q[3]) + "\n";
  }
  return text;
}

/// Appends `value` as `T` in the given byte order.
template <typename T>
void put(std::string& bytes, T value, bool little) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (little != (std::endian::native == std::endian::little)) std::reverse(raw, raw + sizeof(T));
  bytes.append(raw, sizeof(T));
}

/// The cube as binary PLY: float x, double y, float z plus an unused uchar, quads with
/// ushort indices under the name vertex_index, and an extra element that must be skipped.
std::string cube_binary_ply(bool little) {
  std::string bytes = std::string("ply\nformat ") + (little ? "binary_little_endian" : "binary_big_endian") +
                      " 1.0\ncomment test\nelement vertex 8\nproperty float x\nproperty double y\n"
                      "property float z\nproperty uchar quality\nelement face 6\n"
                      "property list uchar ushort vertex_index\nproperty int flags\n"
                      "element edge 1\nproperty list int int pair\nend_header\n";
  for (const Vec3& p : cube_corners) {
    put(bytes, static_cast<float>(p.x()), little);
    put(bytes, p.y(), little);
    put(bytes, static_cast<float>(p.z()), little);
    put(bytes, std::uint8_t{7}, little);
  }
  for (const auto& q : cube_quads) {
    put(bytes, std::uint8_t{4}, little);
    for (int k = 0; k < 4; ++k) put(bytes, static_cast<std::uint16_t>(q[k] - 1), little);
    put(bytes, std::int32_t{-1}, little);
  }
  put(bytes, std::int32_t{2}, little);
  put(bytes, std::int32_t{0}, little);
  put(bytes, std::int32_t{1}, little);
  return bytes;
}

std::string cube_ascii_ply() {
  std::string text =
      "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 6\nproperty list uchar int vertex_indices\nend_header\n";
  for (const Vec3& p : cube_corners) {
    text += std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) + "\n";
  }
  for (const auto& q : cube_quads) {
    text += "4 " + std::to_string(q[0] - 1) + " " + std::to_string(q[1] - 1) + " " + std::to_string(q[2] - 1) + " " +
            std::to_string(q[3] - 1) + "\n";
  }
  return text;
}

/// Same positions (exactly) and same triangles.
void require_same_mesh(const TriangleMesh& a, const TriangleMesh& b) {
  REQUIRE(a.positions.size() == b.positions.size());
  REQUIRE(a.triangles == b.triangles);
  for (std::size_t i = 0; i < a.positions.size(); ++i) REQUIRE(a.positions[i] == b.positions[i]);
}

/// Triangle corner positions of both meshes agree within `tolerance`.
void require_same_triangles(const TriangleMesh& a, const TriangleMesh& b, double tolerance) {
  REQUIRE(a.triangles.size() == b.triangles.size());
  for (std::size_t t = 0; t < a.triangles.size(); ++t) {
    const auto ca = a.corners(t), cb = b.corners(t);
    for (int k = 0; k < 3; ++k) REQUIRE((ca[static_cast<std::size_t>(k)] - cb[static_cast<std::size_t>(k)]).norm() <= tolerance);
  }
}

/// read_model must throw InputError whose message names the file and contains `problem`.
void require_input_error(const fs::path& path, const std::string& problem) {
  try {
    dg::read_model(path);
    FAIL("no InputError for " << path.string());
  } catch (const InputError& error) {
    const std::string message = error.what();
    INFO(message);
    CHECK(message.find(path.string()) == 0);
    CHECK(message.find(problem) != std::string::npos);
    CHECK(message.find('\n') == std::string::npos);
  }
}

/// Reading must either succeed or throw InputError; anything else fails the test.
void require_no_crash(const fs::path& path) {
  try {
    dg::read_model(path);
  } catch (const InputError&) {
  } catch (const std::exception& error) {
    FAIL("unexpected exception for " << path.string() << ": " << error.what());
  }
}

/// A base64 encoder for building data: URIs in tests.
std::string base64(const std::string& bytes) {
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const auto n = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                   static_cast<unsigned char>(bytes[i + 2]);
    out += {alphabet[(n >> 18) & 63], alphabet[(n >> 12) & 63], alphabet[(n >> 6) & 63], alphabet[n & 63]};
  }
  if (i + 1 == bytes.size()) {
    const auto n = static_cast<unsigned char>(bytes[i]) << 16;
    out += {alphabet[(n >> 18) & 63], alphabet[(n >> 12) & 63], '=', '='};
  } else if (i + 2 == bytes.size()) {
    const auto n = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8);
    out += {alphabet[(n >> 18) & 63], alphabet[(n >> 12) & 63], alphabet[(n >> 6) & 63], '='};
  }
  return out;
}

/// Buffer with one triangle: 3 float positions, then 3 ushort indices (padded to 4 bytes).
std::string triangle_buffer() {
  std::string bytes;
  const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  for (float v : xyz) put(bytes, v, true);
  for (std::uint16_t i : {0, 1, 2}) put(bytes, i, true);
  bytes.append(2, '\0');
  return bytes;
}

/// glTF JSON with one triangle mesh instanced twice under a node translated by (0, 0, 10):
/// child 1 adds a translation (1, 0, 0), child 2 a matrix translating by (0, 5, 0).
std::string two_instance_gltf(const std::string& buffer_uri) {
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"translation": [0, 0, 10], "children": [1, 2]},
            {"mesh": 0, "translation": [1, 0, 0]},
            {"mesh": 0, "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,5,0,1]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "buffers": [{"byteLength": 44, "uri": ")" +
         buffer_uri + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]})";
}

void require_two_instances(const Model& model) {
  REQUIRE(model.mesh.triangles.size() == 2);
  REQUIRE(model.mesh.positions.size() == 6);
  CHECK(model.mesh.positions[0] == Vec3(1, 0, 10));
  CHECK(model.mesh.positions[1] == Vec3(2, 0, 10));
  CHECK(model.mesh.positions[2] == Vec3(1, 1, 10));
  CHECK(model.mesh.positions[3] == Vec3(0, 5, 10));
  CHECK(model.mesh.positions[4] == Vec3(1, 5, 10));
  CHECK(model.mesh.positions[5] == Vec3(0, 6, 10));
  CHECK(model.mesh.triangles[1] == dg::Triangle{3, 4, 5});
}

}  // namespace

TEST_CASE("OBJ cube with quads gives 12 triangles and a closed welded mesh", "[geometry][model_io]") {
  const fs::path folder = test_folder("obj-cube");
  write_bytes(folder / "cube.obj", cube_obj());
  Model model = dg::read_model(folder / "cube.obj");
  CHECK(model.source_path == (folder / "cube.obj").string());
  CHECK_FALSE(model.is_point_cloud());
  require_same_mesh(model.mesh, cube_mesh());
  const dg::CleaningReport report = dg::clean_mesh(model.mesh);
  CHECK(report.welded_vertices == 8);
  CHECK(report.triangles == 12);
  CHECK(report.closed_and_oriented);
}

TEST_CASE("OBJ negative indices, corner forms, extra columns and continuation lines", "[geometry][model_io]") {
  const fs::path folder = test_folder("obj-forms");
  write_bytes(folder / "forms.obj",
              "v 0 0 0 1.0\r\n"
              "v 1 0 0 1 0.5 0.5 0.5\r\n"
              "v +1 1 0\r\n"
              "v 0 1 \\\r\n"
              "  0\r\n"
              "vt 0 0\nvn 0 0 1\n"
              "f -4/1/1 -3/1/1 -2/1/1 \\\n -1/1/1\n"
              "f 1//1 3//1 4//1\n"
              "f 1/1 2/1 3/1\n"
              "l 1 2\n"
              "# comment\n");
  const Model model = dg::read_model(folder / "forms.obj");
  REQUIRE(model.mesh.positions.size() == 4);
  CHECK(model.mesh.positions[3] == Vec3(0, 1, 0));
  const std::vector<dg::Triangle> expected = {{0, 1, 2}, {0, 2, 3}, {0, 2, 3}, {0, 1, 2}};
  CHECK(model.mesh.triangles == expected);
}

TEST_CASE("OBJ materials: usemtl per face, Kd colours from mtllib, faces before any usemtl", "[geometry][model_io]") {
  const fs::path folder = test_folder("obj-materials");
  write_bytes(folder / "walls.mtl",
              "newmtl brick red\nKd 0.8 0.2 0.1\nnewmtl glass\nKa 1 1 1\nKd 0.1 0.2 0.9\nnewmtl unused\nKd 1 1 1\n");
  const std::string geometry = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n";
  write_bytes(folder / "walls.obj", "mtllib walls.mtl\n" + geometry +
                                        "f 1 2 3\n"
                                        "usemtl  brick red \nf 1 2 3 4\n"
                                        "usemtl glass\nf 2 5 6\n"
                                        "usemtl brick red\nf 2 6 3\n");
  const Model model = dg::read_model(folder / "walls.obj");
  REQUIRE(model.materials.size() == 3);
  CHECK(model.materials[0].name == "default");
  CHECK(model.materials[1].name == "brick red");
  CHECK(model.materials[1].diffuse.isApprox(Vec3(0.8, 0.2, 0.1)));
  CHECK(model.materials[2].name == "glass");
  CHECK(model.materials[2].diffuse.isApprox(Vec3(0.1, 0.2, 0.9)));
  CHECK(model.mesh.materials == std::vector<std::uint32_t>{0, 1, 1, 2, 1});

  // Cleaning drops the degenerate triangle and its material with it.
  write_bytes(folder / "flat.obj", geometry + "usemtl a\nf 1 2 3\nusemtl b\nf 1 2 5\nusemtl c\nf 2 5 6\n");
  Model flat = dg::read_model(folder / "flat.obj");
  CHECK(flat.materials[0].diffuse == dg::Material{}.diffuse);  // no mtllib: default colours
  dg::clean_mesh(flat.mesh);
  CHECK(flat.mesh.materials == std::vector<std::uint32_t>{0, 2});

  // No usemtl at all: no materials, whatever mtllib says.
  write_bytes(folder / "plain.obj", "mtllib missing.mtl\n" + geometry + "f 1 2 3\n");
  const Model plain = dg::read_model(folder / "plain.obj");
  CHECK(plain.materials.empty());
  CHECK_FALSE(plain.mesh.has_materials());
}

TEST_CASE("OBJ errors name the file and the line", "[geometry][model_io]") {
  const fs::path folder = test_folder("obj-errors");
  write_bytes(folder / "range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n");
  require_input_error(folder / "range.obj", "line 5: face index 4 out of range");
  write_bytes(folder / "relative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n");
  require_input_error(folder / "relative.obj", "line 4");
  write_bytes(folder / "vertex.obj", "v 0 0 0\nv 1 zero 0\n");
  require_input_error(folder / "vertex.obj", "line 2: malformed vertex");
  write_bytes(folder / "zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
  require_input_error(folder / "zero.obj", "line 4");
  write_bytes(folder / "short.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n");
  require_input_error(folder / "short.obj", "line 3: face with fewer than 3 corners");
  write_bytes(folder / "nofaces.obj", "v 0 0 0\nv 1 0 0\n");
  require_input_error(folder / "nofaces.obj", "empty model");
  write_bytes(folder / "nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n");
  require_input_error(folder / "nan.obj", "vertex 1 has a NaN or infinite coordinate");
  write_bytes(folder / "inf.obj", "v 0 0 0\nv 1 0 -inf\nv 0 1 0\nf 1 2 3\n");
  require_input_error(folder / "inf.obj", "NaN or infinite");
  write_bytes(folder / "huge.obj", "v 0 0 0\nv 1 0 2e15\nv 0 1 0\nf 1 2 3\n");
  require_input_error(folder / "huge.obj", "beyond 1e15");
}

TEST_CASE("file-level errors: missing, empty, folder, unknown extension", "[geometry][model_io]") {
  const fs::path folder = test_folder("file-errors");
  require_input_error(folder / "missing.obj", "no such file");
  write_bytes(folder / "empty.ply", "");
  require_input_error(folder / "empty.ply", "empty file");
  fs::create_directories(folder / "dir.obj");
  require_input_error(folder / "dir.obj", "folder");
  write_bytes(folder / "model.fbx", "Kaydara FBX Binary");
  require_input_error(folder / "model.fbx", "unknown model format '.fbx' (supported: .obj .off .ply .stl .gltf .glb .xyz)");
  CHECK_THROWS_AS(dg::write_mesh(folder / "out.stl", cube_mesh()), InputError);
}

TEST_CASE("OFF cube", "[geometry][model_io]") {
  const fs::path folder = test_folder("off");
  std::string text = "OFF\n# the unit cube\n8 6 12\n";
  for (const Vec3& p : cube_corners) text += std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) + "\n";
  for (const auto& q : cube_quads) {
    text += "4 " + std::to_string(q[0] - 1) + " " + std::to_string(q[1] - 1) + " " + std::to_string(q[2] - 1) + " " +
            std::to_string(q[3] - 1) + " 255 0 0\n";
  }
  write_bytes(folder / "cube.off", text);
  require_same_mesh(dg::read_model(folder / "cube.off").mesh, cube_mesh());
  write_bytes(folder / "range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  require_input_error(folder / "range.off", "face index 3 out of range");
  write_bytes(folder / "counts.off", "OFF\n1000000000000 1 0\n0 0 0\n");
  require_input_error(folder / "counts.off", "header claims");
}

TEST_CASE("PLY ascii, binary little and big endian read the same cube", "[geometry][model_io]") {
  const fs::path folder = test_folder("ply");
  write_bytes(folder / "ascii.ply", cube_ascii_ply());
  write_bytes(folder / "little.ply", cube_binary_ply(true));
  write_bytes(folder / "big.ply", cube_binary_ply(false));
  const TriangleMesh expected = cube_mesh();
  require_same_mesh(dg::read_model(folder / "ascii.ply").mesh, expected);
  require_same_mesh(dg::read_model(folder / "little.ply").mesh, expected);
  require_same_mesh(dg::read_model(folder / "big.ply").mesh, expected);
}

TEST_CASE("PLY without faces is a point cloud with normals", "[geometry][model_io]") {
  const fs::path folder = test_folder("ply-cloud");
  write_bytes(folder / "points.ply",
              "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
              "property float nx\nproperty float ny\nproperty float nz\nproperty int segment_index\n"
              "element face 0\nproperty list uchar int vertex_indices\nend_header\n"
              "0 0 0 0 0 1 3\n1 2 3 0 1 0 3\n-1.5 2.5e1 3 1 0 0 4\n");
  const Model model = dg::read_model(folder / "points.ply");
  REQUIRE(model.is_point_cloud());
  REQUIRE(model.cloud.has_normals());
  CHECK(model.cloud.positions[2] == Vec3(-1.5, 25, 3));
  CHECK(model.cloud.normals[1] == Vec3(0, 1, 0));
}

TEST_CASE("malformed PLY files throw InputError naming the file", "[geometry][model_io]") {
  const fs::path folder = test_folder("ply-errors");
  const std::string good = cube_binary_ply(true);
  write_bytes(folder / "truncated.ply", good.substr(0, good.size() - 20));
  require_input_error(folder / "truncated.ply", "truncated");
  write_bytes(folder / "huge.ply",
              "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
              "property float z\nelement face 1000000000000\nproperty list uchar int vertex_indices\nend_header\n" +
                  std::string(36, '\0') + std::string(13, '\0'));
  require_input_error(folder / "huge.ply", "header claims 1000000000000 face elements");
  write_bytes(folder / "range.ply",
              "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
              "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  require_input_error(folder / "range.ply", "face index 7 out of range");
  write_bytes(folder / "nan.ply",
              "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
              "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n");
  require_input_error(folder / "nan.ply", "NaN");
  write_bytes(folder / "noheader.ply", "ply\nformat ascii 1.0\nelement vertex 3\n");
  require_input_error(folder / "noheader.ply", "end_header");
  write_bytes(folder / "magic.ply", "PLY?\n");
  require_input_error(folder / "magic.ply", "not a PLY file");
}

TEST_CASE("STL binary (even with a 'solid' header) and ascii read the same triangles", "[geometry][model_io]") {
  const fs::path folder = test_folder("stl");
  const TriangleMesh cube = cube_mesh();
  std::string binary = "solid but actually binary";
  binary.resize(80, ' ');
  put(binary, static_cast<std::uint32_t>(cube.triangles.size()), true);
  std::string ascii = "solid cube\n";
  for (std::size_t t = 0; t < cube.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) put(binary, 0.0f, true);
    ascii += "  facet normal 0 0 0\n    outer loop\n";
    for (const Vec3& p : cube.corners(t)) {
      for (int k = 0; k < 3; ++k) put(binary, static_cast<float>(p[k]), true);
      ascii += "      vertex " + std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) + "\n";
    }
    put(binary, std::uint16_t{0}, true);
    ascii += "    endloop\n  endfacet\n";
  }
  ascii += "endsolid cube\n";
  write_bytes(folder / "binary.stl", binary);
  write_bytes(folder / "ascii.stl", ascii);
  const Model from_binary = dg::read_model(folder / "binary.stl");
  const Model from_ascii = dg::read_model(folder / "ascii.stl");
  CHECK(from_binary.mesh.positions.size() == 36);
  require_same_mesh(from_binary.mesh, from_ascii.mesh);
  require_same_triangles(from_binary.mesh, cube, 0.0);

  write_bytes(folder / "short.stl", binary.substr(0, binary.size() - 1));
  require_input_error(folder / "short.stl", "binary STL size mismatch");
  write_bytes(folder / "open.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n");
  require_input_error(folder / "open.stl", "truncated");
}

TEST_CASE("glTF: two instances of one mesh under a translated node", "[geometry][model_io]") {
  const fs::path folder = test_folder("gltf");
  const std::string buffer = triangle_buffer();
  write_bytes(folder / "embedded.gltf", two_instance_gltf("data:application/octet-stream;base64," + base64(buffer)));
  require_two_instances(dg::read_model(folder / "embedded.gltf"));

  write_bytes(folder / "two parts.bin", buffer);
  write_bytes(folder / "external.gltf", two_instance_gltf("two%20parts.bin"));
  require_two_instances(dg::read_model(folder / "external.gltf"));

  write_bytes(folder / "missing.gltf", two_instance_gltf("nowhere.bin"));
  require_input_error(folder / "missing.gltf", "cannot read buffer file");
  write_bytes(folder / "broken.gltf", "{\"asset\": {\"version\": \"2.0\"}, ");
  require_input_error(folder / "broken.gltf", "invalid glTF JSON");
}

TEST_CASE("glTF materials: each primitive's triangles get its material and baseColorFactor", "[geometry][model_io]") {
  const fs::path folder = test_folder("gltf-materials");
  const std::string uri = "data:application/octet-stream;base64," + base64(triangle_buffer());
  std::string text = two_instance_gltf(uri);
  const std::string primitive = R"({"attributes": {"POSITION": 0}, "indices": 1})";
  const std::string with_materials = R"({"attributes": {"POSITION": 0}, "indices": 1, "material": 1},
      {"attributes": {"POSITION": 0}, "indices": 1}, {"attributes": {"POSITION": 0}, "indices": 1, "material": 0})";
  text.replace(text.find(primitive), primitive.size(), with_materials);
  text.replace(text.find(R"("buffers")"), 0, R"("materials": [{"name": "stone"},
      {"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.25, 1.0, 0.5]}}], )");
  write_bytes(folder / "materials.gltf", text);
  const Model model = dg::read_model(folder / "materials.gltf");
  REQUIRE(model.mesh.triangles.size() == 6);
  REQUIRE(model.materials.size() == 3);
  CHECK(model.materials[0].name == "material 1");
  CHECK(model.materials[0].diffuse == Vec3(0.5, 0.25, 1.0));
  CHECK(model.materials[0].opacity == 1.0);  // alpha 0.5, but alphaMode OPAQUE (the default) ignores it
  CHECK(model.materials[1].name == "default");
  CHECK(model.materials[2].name == "stone");
  CHECK(model.materials[2].diffuse == Vec3(1.0, 1.0, 1.0));
  CHECK(model.mesh.materials == std::vector<std::uint32_t>{0, 1, 2, 0, 1, 2});

  write_bytes(folder / "plain.gltf", two_instance_gltf(uri));
  CHECK_FALSE(dg::read_model(folder / "plain.gltf").mesh.has_materials());
}

TEST_CASE("glTF: rotation, scale, mirrored transforms, strips and fans", "[geometry][model_io]") {
  const fs::path folder = test_folder("gltf-modes");
  std::string buffer;
  const float xyz[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  for (float v : xyz) put(buffer, v, true);
  const std::string uri = "data:application/gltf-buffer;base64," + base64(buffer);
  const std::string json = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1, 2]}],
    "nodes": [{"mesh": 0, "rotation": [0, 0, 0.7071067811865476, 0.7071067811865476], "scale": [2, 2, 2]},
              {"mesh": 1, "scale": [-1, 1, 1]},
              {"mesh": 2}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "mode": 4}]},
               {"primitives": [{"attributes": {"POSITION": 0}, "mode": 5}]},
               {"primitives": [{"attributes": {"POSITION": 0}, "mode": 6}, {"attributes": {"POSITION": 0}, "mode": 1}]}],
    "buffers": [{"byteLength": 48, "uri": ")" + uri + R"("}],
    "bufferViews": [{"buffer": 0, "byteLength": 48}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"}]})";
  write_bytes(folder / "modes.gltf", json);
  const Model model = dg::read_model(folder / "modes.gltf");
  const TriangleMesh& mesh = model.mesh;
  // Triangle list: 4 vertices -> 1 triangle (the 4th vertex is left over); rotated 90 degrees about z, scaled 2.
  // Strip: 2 triangles, mirrored in x so the winding is reversed. Fan: 2 triangles. Lines are skipped.
  REQUIRE(mesh.triangles.size() == 5);
  REQUIRE(mesh.positions.size() == 12);
  CHECK((mesh.positions[1] - Vec3(0, 2, 0)).norm() < 1e-12);
  CHECK((mesh.positions[2] - Vec3(-2, 0, 0)).norm() < 1e-12);
  CHECK(mesh.triangles[0] == dg::Triangle{0, 1, 2});
  CHECK(mesh.positions[5] == Vec3(-1, 0, 0));
  CHECK(mesh.triangles[1] == dg::Triangle{4, 6, 5});
  CHECK(mesh.triangles[2] == dg::Triangle{5, 6, 7});
  CHECK(mesh.triangles[3] == dg::Triangle{9, 10, 8});
  CHECK(mesh.triangles[4] == dg::Triangle{10, 11, 8});
  for (std::size_t t = 0; t < 4; ++t) CHECK(mesh.area_vector(t).z() > 0.0);  // orientation survives the mirror
}

TEST_CASE("glTF errors: out-of-range accessors and indices, truncated GLB", "[geometry][model_io]") {
  const fs::path folder = test_folder("gltf-errors");
  std::string buffer = triangle_buffer();
  buffer[36] = 9;  // first index becomes 9
  write_bytes(folder / "index.gltf", two_instance_gltf("data:application/octet-stream;base64," + base64(buffer)));
  require_input_error(folder / "index.gltf", "out of range");
  write_bytes(folder / "short.gltf", two_instance_gltf("data:application/octet-stream;base64," + base64(buffer.substr(0, 20))));
  require_input_error(folder / "short.gltf", "shorter than its byteLength");

  dg::write_mesh(folder / "cube.glb", cube_mesh());
  const std::string glb = read_bytes(folder / "cube.glb");
  write_bytes(folder / "truncated.glb", glb.substr(0, glb.size() - 10));
  require_input_error(folder / "truncated.glb", "truncated");
  write_bytes(folder / "magic.glb", "glTf" + glb.substr(4));
  require_input_error(folder / "magic.glb", "not a GLB file");
}

TEST_CASE("XYZ points with and without normals", "[geometry][model_io]") {
  const fs::path folder = test_folder("xyz");
  write_bytes(folder / "plain.xyz", "# points\n0 0 0\n1 2 3\n\n4 5 6\n");
  const Model plain = dg::read_model(folder / "plain.xyz");
  REQUIRE(plain.is_point_cloud());
  CHECK(plain.cloud.positions.size() == 3);
  CHECK_FALSE(plain.cloud.has_normals());
  write_bytes(folder / "normals.xyz", "0 0 0 0 0 1\n1 2 3 1 0 0\n");
  const Model with_normals = dg::read_model(folder / "normals.xyz");
  REQUIRE(with_normals.cloud.has_normals());
  CHECK(with_normals.cloud.normals[1] == Vec3(1, 0, 0));
  write_bytes(folder / "mixed.xyz", "0 0 0 0 0 1\n1 2 3\n");
  require_input_error(folder / "mixed.xyz", "line 2");
  write_bytes(folder / "words.xyz", "0 0 0\nx y z\n");
  require_input_error(folder / "words.xyz", "line 2: malformed point");
}

TEST_CASE("write then read gives the same geometry, byte-identical on repeat", "[geometry][model_io]") {
  const fs::path folder = test_folder("round-trip");
  TriangleMesh mesh = cube_mesh();
  mesh.positions[6] = Vec3(0.1 + 0.2, -1.0 / 3.0, 1e-300);  // needs all 17 digits
  mesh.positions[7] = Vec3(123456.789012345678, -0.0, 2.5e14);
  std::vector<dg::Rgb> colors(mesh.positions.size(), dg::Rgb{10, 200, 30});
  colors[3] = {255, 0, 128};

  dg::write_mesh(folder / "mesh.obj", mesh);
  require_same_mesh(dg::read_model(folder / "mesh.obj").mesh, mesh);
  dg::write_mesh(folder / "mesh.ply", mesh, &colors);
  require_same_mesh(dg::read_model(folder / "mesh.ply").mesh, mesh);
  dg::write_mesh(folder / "plain.ply", mesh);
  require_same_mesh(dg::read_model(folder / "plain.ply").mesh, mesh);

  TriangleMesh unit = cube_mesh();
  dg::write_mesh(folder / "mesh.glb", unit, &colors);
  require_same_mesh(dg::read_model(folder / "mesh.glb").mesh, unit);  // exact in float
  dg::write_mesh(folder / "lossy.glb", mesh);
  const Model glb = dg::read_model(folder / "lossy.glb");
  REQUIRE(glb.mesh.triangles == mesh.triangles);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    CHECK(glb.mesh.positions[i].x() == static_cast<double>(static_cast<float>(mesh.positions[i].x())));
  }

  for (const char* name : {"mesh.obj", "mesh.ply", "mesh.glb"}) {
    const std::string first = read_bytes(folder / name);
    const fs::path again = folder / (std::string("again-") + name);
    if (std::string(name) == "mesh.obj") dg::write_mesh(again, mesh);
    if (std::string(name) == "mesh.ply") dg::write_mesh(again, mesh, &colors);
    if (std::string(name) == "mesh.glb") dg::write_mesh(again, unit, &colors);
    CHECK(read_bytes(again) == first);
  }
  // No temporary files are left behind.
  for (const auto& entry : fs::directory_iterator(folder)) {
    CHECK(entry.path().filename().string().find(".tmp-") == std::string::npos);
  }
}

TEST_CASE("GLB output follows the glTF container layout", "[geometry][model_io]") {
  const fs::path folder = test_folder("glb-layout");
  std::vector<dg::Rgb> colors(8, dg::Rgb{1, 2, 3});
  dg::write_mesh(folder / "cube.glb", cube_mesh(), &colors);
  const std::string glb = read_bytes(folder / "cube.glb");
  REQUIRE(glb.substr(0, 4) == "glTF");
  std::uint32_t header[3], json_length = 0;
  std::memcpy(header, glb.data(), 12);
  std::memcpy(&json_length, glb.data() + 12, 4);
  CHECK(header[1] == 2);
  CHECK(header[2] == glb.size());
  CHECK(json_length % 4 == 0);
  CHECK(glb.size() % 4 == 0);
  const std::string json = glb.substr(20, json_length);
  CHECK(json.find(R"("max":[1.0,1.0,1.0])") != std::string::npos);
  CHECK(json.find(R"("min":[0.0,0.0,0.0])") != std::string::npos);
  CHECK(json.find(R"("COLOR_0":2)") != std::string::npos);
  CHECK(json.find(R"("byteStride":4)") != std::string::npos);

  dg::write_mesh(folder / "empty.glb", TriangleMesh{});
  require_input_error(folder / "empty.glb", "empty model");
}

TEST_CASE("garbage and truncated files never crash the readers", "[geometry][model_io]") {
  const fs::path folder = test_folder("garbage");
  std::uint32_t state = 12345;
  auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return static_cast<char>(state >> 24);
  };
  for (const char* extension : {".obj", ".off", ".ply", ".stl", ".gltf", ".glb", ".xyz"}) {
    for (int trial = 0; trial < 20; ++trial) {
      std::string bytes(static_cast<std::size_t>(1 + trial * 37), '\0');
      std::generate(bytes.begin(), bytes.end(), next);
      const fs::path path = folder / (std::string("garbage") + extension);
      write_bytes(path, bytes);
      require_no_crash(path);
    }
  }
  dg::write_mesh(folder / "cube.glb", cube_mesh());
  dg::write_mesh(folder / "cube.ply", cube_mesh());
  const std::string glb = read_bytes(folder / "cube.glb");
  const std::string ply = read_bytes(folder / "cube.ply");
  const std::string little = cube_binary_ply(true);
  for (std::size_t n = 0; n < glb.size(); n += 3) {
    write_bytes(folder / "cut.glb", glb.substr(0, n));
    require_no_crash(folder / "cut.glb");
  }
  for (std::size_t n = 0; n < little.size(); n += 2) {
    write_bytes(folder / "cut.ply", little.substr(0, n));
    require_no_crash(folder / "cut.ply");
    write_bytes(folder / "cut2.ply", ply.substr(0, std::min(n, ply.size())));
    require_no_crash(folder / "cut2.ply");
  }
  const std::string ascii = cube_ascii_ply();
  for (std::size_t n = 0; n < ascii.size(); ++n) {
    std::string damaged = ascii;
    damaged[n] = '~';
    write_bytes(folder / "damaged.ply", damaged);
    require_no_crash(folder / "damaged.ply");
  }
}

TEST_CASE("a 500k-triangle OBJ with v/vt corners reads completely", "[geometry][model_io]") {
  const fs::path folder = test_folder("large");
  const int n = 500;  // n x n quads -> 500,000 triangles
  std::string text;
  text.reserve(30'000'000);
  for (int y = 0; y <= n; ++y) {
    for (int x = 0; x <= n; ++x) {
      text += "v " + std::to_string(x * 0.013) + " " + std::to_string(y * 0.017) + " " +
              std::to_string(std::sin(x * 0.1) * std::cos(y * 0.1)) + "\n";
    }
  }
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const int a = y * (n + 1) + x + 1;
      text += "f " + std::to_string(a) + "/" + std::to_string(a) + " " + std::to_string(a + 1) + " " +
              std::to_string(a + n + 2) + " " + std::to_string(a + n + 1) + "\n";
    }
  }
  write_bytes(folder / "grid.obj", text);
  // Read speed is measured by the benchmark driver, not asserted here.
  const Model model = dg::read_model(folder / "grid.obj");
  REQUIRE(model.mesh.triangles.size() == 500'000);
  REQUIRE(model.mesh.positions.size() == 501u * 501u);
  fs::remove_all(folder);
}
