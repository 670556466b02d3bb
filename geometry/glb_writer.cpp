// GLB writer: glTF 2.0 binary container with one scene, one node and one mesh.

#include "geometry/mesh_writer.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>

namespace dg::detail {

namespace {

using nlohmann::json;

constexpr int array_buffer = 34962;
constexpr int element_array_buffer = 34963;

void append_chunk(std::string& file, std::uint32_t type, std::string data, char padding) {
  while (data.size() % 4 != 0) data.push_back(padding);
  append_le(file, static_cast<std::uint32_t>(data.size()));
  append_le(file, type);
  file += data;
}

}  // namespace

void write_glb(std::ostream& out, const TriangleMesh& mesh, const std::vector<Rgb>* colors) {
  json document = {{"asset", {{"version", "2.0"}, {"generator", "dockgrammar"}}}, {"scene", 0}};
  std::string binary;
  if (mesh.positions.empty() || mesh.triangles.empty()) {
    document["scenes"] = json::array({json::object()});
  } else {
    const std::size_t n = mesh.positions.size();
    std::array<float, 3> low{}, high{};
    low.fill(std::numeric_limits<float>::infinity());
    high.fill(-std::numeric_limits<float>::infinity());
    binary.reserve(n * 16 + mesh.triangles.size() * 12);
    for (const Vec3& p : mesh.positions) {
      for (int axis = 0; axis < 3; ++axis) {
        const auto value = static_cast<float>(p[axis]);
        low[static_cast<std::size_t>(axis)] = std::min(low[static_cast<std::size_t>(axis)], value);
        high[static_cast<std::size_t>(axis)] = std::max(high[static_cast<std::size_t>(axis)], value);
        append_le(binary, value);
      }
    }
    const std::size_t positions_bytes = binary.size();
    for (const Triangle& t : mesh.triangles) {
      for (std::uint32_t index : t) append_le(binary, index);
    }
    const std::size_t indices_bytes = binary.size() - positions_bytes;
    json attributes = {{"POSITION", 0}};
    json views = json::array({
        {{"buffer", 0}, {"byteOffset", 0}, {"byteLength", positions_bytes}, {"target", array_buffer}},
        {{"buffer", 0}, {"byteOffset", positions_bytes}, {"byteLength", indices_bytes}, {"target", element_array_buffer}},
    });
    json accessors = json::array({
        {{"bufferView", 0}, {"componentType", 5126}, {"count", n}, {"type", "VEC3"}, {"min", low}, {"max", high}},
        {{"bufferView", 1}, {"componentType", 5125}, {"count", 3 * mesh.triangles.size()}, {"type", "SCALAR"}},
    });
    if (colors) {
      // Each vertex attribute element must start on a 4-byte boundary, hence a stride of 4.
      const std::size_t colors_offset = binary.size();
      for (const Rgb& c : *colors) {
        binary.append({static_cast<char>(c[0]), static_cast<char>(c[1]), static_cast<char>(c[2]), '\0'});
      }
      views.push_back({{"buffer", 0},
                       {"byteOffset", colors_offset},
                       {"byteLength", binary.size() - colors_offset},
                       {"byteStride", 4},
                       {"target", array_buffer}});
      accessors.push_back(
          {{"bufferView", 2}, {"componentType", 5121}, {"normalized", true}, {"count", n}, {"type", "VEC3"}});
      attributes["COLOR_0"] = 2;
    }
    document["scenes"] = json::array({{{"nodes", json::array({0})}}});
    document["nodes"] = json::array({{{"mesh", 0}}});
    document["meshes"] = json::array({{{"primitives", json::array({{{"attributes", attributes}, {"indices", 1}, {"mode", 4}}})}}});
    document["buffers"] = json::array({{{"byteLength", binary.size()}}});
    document["bufferViews"] = std::move(views);
    document["accessors"] = std::move(accessors);
  }

  std::string chunks;
  append_chunk(chunks, 0x4E4F534Au, document.dump(), ' ');
  if (!binary.empty()) append_chunk(chunks, 0x004E4942u, std::move(binary), '\0');
  std::string file = "glTF";
  append_le(file, std::uint32_t{2});
  append_le(file, static_cast<std::uint32_t>(12 + chunks.size()));
  file += chunks;
  out.write(file.data(), static_cast<std::streamsize>(file.size()));
}

}  // namespace dg::detail
