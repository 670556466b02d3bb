// GLB writer: glTF 2.0 binary container with one scene, one node and one mesh.

#include "geometry/mesh_writer.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

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

// The triangles of each primitive: all in order, or with `materials` one list per material
// used (ascending material), paired with the material (-1: none).
std::vector<std::pair<int, std::vector<std::size_t>>> primitive_triangles(const TriangleMesh& mesh,
                                                                          const std::vector<Material>* materials) {
  if (!materials) {
    std::vector<std::size_t> all(mesh.triangles.size());
    for (std::size_t t = 0; t < all.size(); ++t) all[t] = t;
    return {{-1, std::move(all)}};
  }
  std::vector<std::vector<std::size_t>> by_material(materials->size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) by_material[mesh.materials[t]].push_back(t);
  std::vector<std::pair<int, std::vector<std::size_t>>> groups;
  for (std::size_t m = 0; m < by_material.size(); ++m)
    if (!by_material[m].empty()) groups.emplace_back(static_cast<int>(m), std::move(by_material[m]));
  return groups;
}

json material_json(const Material& material) {
  const Vec3& c = material.diffuse;
  json result = {{"name", material.name},
                 {"pbrMetallicRoughness",
                  {{"baseColorFactor", {c.x(), c.y(), c.z(), material.opacity}}, {"metallicFactor", 0.0}, {"roughnessFactor", 1.0}}}};
  if (material.opacity < 1.0) result["alphaMode"] = "BLEND";
  return result;
}

}  // namespace

void write_glb(std::ostream& out, const TriangleMesh& mesh, const std::vector<Rgb>* colors,
               const std::vector<Material>* materials) {
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
    json accessors = json::array(
        {{{"bufferView", 0}, {"componentType", 5126}, {"count", n}, {"type", "VEC3"}, {"min", low}, {"max", high}}});
    const auto groups = primitive_triangles(mesh, materials);
    for (const auto& [material, triangles] : groups) {
      json indices = {{"bufferView", 1}, {"componentType", 5125}, {"count", 3 * triangles.size()}, {"type", "SCALAR"}};
      if (binary.size() > positions_bytes) indices["byteOffset"] = binary.size() - positions_bytes;
      accessors.push_back(std::move(indices));
      for (std::size_t t : triangles) {
        for (std::uint32_t index : mesh.triangles[t]) append_le(binary, index);
      }
    }
    const std::size_t indices_bytes = binary.size() - positions_bytes;
    json attributes = {{"POSITION", 0}};
    json views = json::array({
        {{"buffer", 0}, {"byteOffset", 0}, {"byteLength", positions_bytes}, {"target", array_buffer}},
        {{"buffer", 0}, {"byteOffset", positions_bytes}, {"byteLength", indices_bytes}, {"target", element_array_buffer}},
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
      attributes["COLOR_0"] = accessors.size();
      accessors.push_back(
          {{"bufferView", 2}, {"componentType", 5121}, {"normalized", true}, {"count", n}, {"type", "VEC3"}});
    }
    json primitives = json::array();
    for (std::size_t g = 0; g < groups.size(); ++g) {
      json primitive = {{"attributes", attributes}, {"indices", g + 1}, {"mode", 4}};
      if (groups[g].first >= 0) primitive["material"] = groups[g].first;
      primitives.push_back(std::move(primitive));
    }
    if (materials) {
      json list = json::array();
      for (const Material& m : *materials) list.push_back(material_json(m));
      document["materials"] = std::move(list);
    }
    document["scenes"] = json::array({{{"nodes", json::array({0})}}});
    document["nodes"] = json::array({{{"mesh", 0}}});
    document["meshes"] = json::array({{{"primitives", std::move(primitives)}}});
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
