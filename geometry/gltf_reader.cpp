// glTF 2.0 reader (.gltf JSON with external or data: URI buffers, .glb binary container).
// Every mesh instance of the default scene is placed with its node's world transform;
// triangle lists, strips and fans are read, other primitive modes (points, lines) are skipped.

#include "geometry/errors.h"
#include "geometry/model_reader.h"
#include "geometry/text_reader.h"

#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

namespace dg::detail {

namespace {

using nlohmann::json;

std::uint32_t u32_le(std::string_view bytes, std::size_t offset) {
  unsigned char b[4];
  std::memcpy(b, bytes.data() + offset, 4);
  return static_cast<std::uint32_t>(b[0]) | (static_cast<std::uint32_t>(b[1]) << 8) |
         (static_cast<std::uint32_t>(b[2]) << 16) | (static_cast<std::uint32_t>(b[3]) << 24);
}

/// Decodes standard base64 (padding optional); nullopt on an invalid character.
std::optional<std::string> decode_base64(std::string_view text) {
  std::string out;
  out.reserve(text.size() / 4 * 3 + 3);
  std::uint32_t accumulator = 0;
  int bits = 0;
  for (char c : text) {
    int value = 0;
    if (c >= 'A' && c <= 'Z') {
      value = c - 'A';
    } else if (c >= 'a' && c <= 'z') {
      value = c - 'a' + 26;
    } else if (c >= '0' && c <= '9') {
      value = c - '0' + 52;
    } else if (c == '+' || c == '-') {
      value = 62;
    } else if (c == '/' || c == '_') {
      value = 63;
    } else if (c == '=') {
      break;
    } else {
      return std::nullopt;
    }
    accumulator = (accumulator << 6) | static_cast<std::uint32_t>(value);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<char>((accumulator >> bits) & 0xFFu));
    }
  }
  return out;
}

/// Decodes %XX escapes in a relative URI.
std::string decode_percent(std::string_view uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      out.push_back(static_cast<char>(std::stoi(std::string(uri.substr(i + 1, 2)), nullptr, 16)));
      i += 2;
    } else {
      out.push_back(uri[i]);
    }
  }
  return out;
}

/// The parsed document plus its loaded buffers; all lookups are bounds-checked.
class GltfDocument {
 public:
  GltfDocument(const std::filesystem::path& path, json document, std::string_view glb_binary)
      : path_(path), name_(path.string()), doc_(std::move(document)), glb_binary_(glb_binary) {
    if (doc_.contains("extensionsRequired")) {
      for (const json& extension : doc_.at("extensionsRequired")) {
        const std::string ext = extension.get<std::string>();
        if (ext != "KHR_mesh_quantization" && ext.rfind("KHR_materials", 0) != 0 && ext != "KHR_texture_transform") {
          fail("required extension " + ext + " is not supported");
        }
      }
    }
    buffers_.resize(array("buffers").size());
  }

  [[noreturn]] void fail(const std::string& problem) const { throw InputError(name_ + ": " + problem); }

  /// Top-level array `key` (empty when absent).
  const json& array(const char* key) const {
    static const json empty = json::array();
    if (!doc_.contains(key)) return empty;
    const json& value = doc_.at(key);
    if (!value.is_array()) fail(std::string("'") + key + "' is not an array");
    return value;
  }
  /// Element `index` of top-level array `key`.
  const json& item(const char* key, const json& index) const {
    const json& list = array(key);
    const std::size_t i = index.get<std::size_t>();
    if (i >= list.size()) fail(std::string(key) + " index " + std::to_string(i) + " out of range");
    return list[i];
  }
  const json& root() const { return doc_; }

  /// Reads accessor `index` as `components` doubles per element (normalized integers mapped to [-1, 1] / [0, 1]).
  std::vector<double> read_accessor(const json& index, std::size_t components) const {
    const json& accessor = item("accessors", index);
    if (accessor.contains("sparse")) fail("sparse accessors are not supported");
    const std::string type = accessor.at("type").get<std::string>();
    const std::size_t type_components = type == "SCALAR" ? 1 : type == "VEC2" ? 2 : type == "VEC3" ? 3
                                        : type == "VEC4" ? 4 : 0;
    if (type_components != components) fail("accessor " + index.dump() + " has type " + type);
    const int component_type = accessor.at("componentType").get<int>();
    const std::size_t component_size = component_type == 5120 || component_type == 5121   ? 1
                                       : component_type == 5122 || component_type == 5123 ? 2
                                       : component_type == 5125 || component_type == 5126 ? 4
                                                                                          : 0;
    if (component_size == 0) fail("accessor " + index.dump() + " has unknown componentType " + std::to_string(component_type));
    const bool normalized = accessor.value("normalized", false);
    const std::uint64_t count = accessor.at("count").get<std::uint64_t>();
    const std::size_t element_size = component_size * components;
    std::vector<double> values;
    if (!accessor.contains("bufferView")) {
      if (count > (std::uint64_t{1} << 20)) fail("accessor " + index.dump() + " without bufferView is too large");
      values.assign(count * components, 0.0);
      return values;
    }
    const json& view = item("bufferViews", accessor.at("bufferView"));
    const std::string_view buffer = load_buffer(view.at("buffer").get<std::size_t>());
    const std::uint64_t view_offset = view.value("byteOffset", std::uint64_t{0});
    const std::uint64_t view_length = view.at("byteLength").get<std::uint64_t>();
    if (view_offset > buffer.size() || view_length > buffer.size() - view_offset) {
      fail("bufferView " + accessor.at("bufferView").dump() + " exceeds its buffer");
    }
    const std::uint64_t stride = view.value("byteStride", std::uint64_t{element_size});
    const std::uint64_t offset = accessor.value("byteOffset", std::uint64_t{0});
    if (stride < element_size) fail("bufferView byteStride is smaller than an element");
    if (count > 0 && (count > view_length || offset > view_length ||
                      (count - 1) > (view_length - offset) / stride ||
                      offset + (count - 1) * stride + element_size > view_length)) {
      fail("accessor " + index.dump() + " exceeds its bufferView");
    }
    values.resize(count * components);
    const char* base = buffer.data() + view_offset + offset;
    for (std::uint64_t i = 0; i < count; ++i) {
      const char* element = base + i * stride;
      for (std::size_t c = 0; c < components; ++c) {
        values[i * components + c] = decode(element + c * component_size, component_type, normalized);
      }
    }
    return values;
  }

 private:
  static double decode(const char* p, int component_type, bool normalized) {
    unsigned char raw[4];
    switch (component_type) {
      case 5120: {
        std::int8_t v;
        std::memcpy(&v, p, 1);
        return normalized ? std::max(v / 127.0, -1.0) : v;
      }
      case 5121: {
        std::uint8_t v;
        std::memcpy(&v, p, 1);
        return normalized ? v / 255.0 : v;
      }
      case 5122: {
        std::memcpy(raw, p, 2);
        const auto v = static_cast<std::int16_t>(raw[0] | (raw[1] << 8));
        return normalized ? std::max(v / 32767.0, -1.0) : v;
      }
      case 5123: {
        std::memcpy(raw, p, 2);
        const auto v = static_cast<std::uint16_t>(raw[0] | (raw[1] << 8));
        return normalized ? v / 65535.0 : v;
      }
      case 5125:
        return static_cast<double>(u32_le(std::string_view(p, 4), 0));
      default:
        return static_cast<double>(std::bit_cast<float>(u32_le(std::string_view(p, 4), 0)));
    }
  }

  std::string_view load_buffer(std::size_t index) const {
    const json& buffers = array("buffers");
    if (index >= buffers.size()) fail("buffer index " + std::to_string(index) + " out of range");
    std::optional<std::string>& data = buffers_[index];
    const json& buffer = buffers[index];
    const std::uint64_t length = buffer.at("byteLength").get<std::uint64_t>();
    if (!buffer.contains("uri")) {
      if (index != 0 || glb_binary_.data() == nullptr) fail("buffer " + std::to_string(index) + " has no uri");
      if (glb_binary_.size() < length) fail("GLB binary chunk is shorter than buffer 0");
      return glb_binary_.substr(0, length);
    }
    if (!data) {
      const std::string uri = buffer.at("uri").get<std::string>();
      if (uri.rfind("data:", 0) == 0) {
        const std::size_t comma = uri.find(',');
        if (comma == std::string::npos || uri.substr(0, comma).find(";base64") == std::string::npos) {
          fail("buffer " + std::to_string(index) + " has a data URI that is not base64");
        }
        data = decode_base64(std::string_view(uri).substr(comma + 1));
        if (!data) fail("buffer " + std::to_string(index) + " has invalid base64 data");
      } else {
        const std::filesystem::path file = path_.parent_path() / decode_percent(uri);
        std::ifstream in(file, std::ios::binary);
        if (!in) fail("cannot read buffer file " + file.string());
        data = std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
      }
    }
    if (data->size() < length) fail("buffer " + std::to_string(index) + " is shorter than its byteLength");
    return std::string_view(*data).substr(0, length);
  }

  std::filesystem::path path_;
  std::string name_;
  json doc_;
  std::string_view glb_binary_;
  mutable std::vector<std::optional<std::string>> buffers_;
};

/// Local transform of a node (matrix, or translation * rotation * scale).
Mat4 local_transform(const GltfDocument& doc, const json& node) {
  Mat4 m = Mat4::Identity();
  if (node.contains("matrix")) {
    const std::vector<double> values = node.at("matrix").get<std::vector<double>>();
    if (values.size() != 16) doc.fail("node matrix does not have 16 numbers");
    for (int column = 0; column < 4; ++column) {
      for (int row = 0; row < 4; ++row) m(row, column) = values[static_cast<std::size_t>(column * 4 + row)];
    }
    return m;
  }
  if (node.contains("scale")) {
    const auto s = node.at("scale").get<std::vector<double>>();
    if (s.size() != 3) doc.fail("node scale does not have 3 numbers");
    m.topLeftCorner<3, 3>() = Vec3(s[0], s[1], s[2]).asDiagonal();
  }
  if (node.contains("rotation")) {
    const auto q = node.at("rotation").get<std::vector<double>>();
    if (q.size() != 4) doc.fail("node rotation does not have 4 numbers");
    Eigen::Quaterniond quaternion(q[3], q[0], q[1], q[2]);
    if (!(quaternion.norm() > 0.0)) doc.fail("node rotation is not a valid quaternion");
    quaternion.normalize();
    m.topLeftCorner<3, 3>() = quaternion.toRotationMatrix() * m.topLeftCorner<3, 3>();
  }
  if (node.contains("translation")) {
    const auto t = node.at("translation").get<std::vector<double>>();
    if (t.size() != 3) doc.fail("node translation does not have 3 numbers");
    m.topRightCorner<3, 1>() = Vec3(t[0], t[1], t[2]);
  }
  return m;
}

/// Index into model.materials for a primitive's material (glTF index, or -1 for none), adding the
/// material on first use: its name (or "material N"), baseColorFactor as the diffuse colour (and,
/// with alphaMode BLEND, its alpha as the opacity).
std::uint32_t model_material(const GltfDocument& doc, std::int64_t gltf_index, std::map<std::int64_t, std::uint32_t>& known,
                             std::vector<Material>& materials) {
  const auto found = known.find(gltf_index);
  if (found != known.end()) return found->second;
  Material material{"default"};
  if (gltf_index >= 0) {
    const json& source = doc.item("materials", json(gltf_index));
    material.name = source.value("name", std::string());
    if (material.name.empty()) material.name = "material " + std::to_string(gltf_index);
    const json pbr = source.value("pbrMetallicRoughness", json::object());
    const auto factor = pbr.value("baseColorFactor", std::vector<double>{1.0, 1.0, 1.0, 1.0});
    if (factor.size() < 3) doc.fail("baseColorFactor of material " + std::to_string(gltf_index) + " has fewer than 3 numbers");
    material.diffuse = Vec3(factor[0], factor[1], factor[2]).cwiseMax(0.0).cwiseMin(1.0);
    // Alpha only counts in BLEND mode (OPAQUE, the default, ignores it; MASK cuts, it does not blend).
    if (factor.size() >= 4 && source.value("alphaMode", std::string("OPAQUE")) == "BLEND")
      material.opacity = std::clamp(factor[3], 0.0, 1.0);
  }
  const auto index = static_cast<std::uint32_t>(materials.size());
  materials.push_back(std::move(material));
  known.emplace(gltf_index, index);
  return index;
}

/// Appends the triangles of one primitive, transformed by `world`, to `mesh`.
void add_primitive(const GltfDocument& doc, const json& primitive, const Mat4& world, TriangleMesh& mesh) {
  const int mode = primitive.value("mode", 4);
  if (mode != 4 && mode != 5 && mode != 6) return;  // points and lines carry no surface
  const json& attributes = primitive.at("attributes");
  if (!attributes.contains("POSITION")) doc.fail("mesh primitive without POSITION");
  const std::vector<double> xyz = doc.read_accessor(attributes.at("POSITION"), 3);
  const std::size_t vertex_count = xyz.size() / 3;
  std::vector<std::uint32_t> indices;
  if (primitive.contains("indices")) {
    const std::vector<double> raw = doc.read_accessor(primitive.at("indices"), 1);
    indices.reserve(raw.size());
    for (double value : raw) {
      if (!(value >= 0.0) || value >= static_cast<double>(vertex_count) || value != std::floor(value)) {
        doc.fail("index " + format_number(value) + " out of range (primitive has " + std::to_string(vertex_count) +
                 " vertices)");
      }
      indices.push_back(static_cast<std::uint32_t>(value));
    }
  } else {
    indices.resize(vertex_count);
    for (std::size_t i = 0; i < vertex_count; ++i) indices[i] = static_cast<std::uint32_t>(i);
  }
  if (mesh.positions.size() + vertex_count > std::numeric_limits<std::uint32_t>::max()) {
    doc.fail("too many vertices");
  }
  const auto first = static_cast<std::uint32_t>(mesh.positions.size());
  const Eigen::Matrix3d linear = world.topLeftCorner<3, 3>();
  const Vec3 translation = world.topRightCorner<3, 1>();
  for (std::size_t i = 0; i < vertex_count; ++i) {
    mesh.positions.push_back(linear * Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]) + translation);
  }
  const bool mirrored = linear.determinant() < 0.0;
  auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (mirrored) std::swap(b, c);
    mesh.triangles.push_back({first + a, first + b, first + c});
  };
  const std::size_t n = indices.size();
  if (mode == 4) {
    for (std::size_t i = 0; i + 2 < n; i += 3) add(indices[i], indices[i + 1], indices[i + 2]);
  } else if (mode == 5) {
    for (std::size_t i = 0; i + 2 < n; ++i) {
      if (i % 2 == 0) {
        add(indices[i], indices[i + 1], indices[i + 2]);
      } else {
        add(indices[i], indices[i + 2], indices[i + 1]);
      }
    }
  } else {
    for (std::size_t i = 1; i + 1 < n; ++i) add(indices[i], indices[i + 1], indices[0]);
  }
}

/// Adds the meshes of the hierarchy below `root` (depth first, children in order). Every node
/// may be reached once per scene (glTF nodes form strict trees), which also rules out cycles.
/// Each primitive's triangles get its material (`known` maps glTF material indices to the model's).
void add_hierarchy(const GltfDocument& doc, const json& root, std::vector<bool>& visited,
                   std::map<std::int64_t, std::uint32_t>& known, Model& model) {
  std::vector<std::pair<json, Mat4>> stack{{root, Mat4::Identity()}};
  while (!stack.empty()) {
    const auto [node_index, parent] = stack.back();
    stack.pop_back();
    const json& node = doc.item("nodes", node_index);
    const std::size_t i = node_index.get<std::size_t>();
    if (visited[i]) doc.fail("node " + std::to_string(i) + " appears twice in the scene hierarchy");
    visited[i] = true;
    const Mat4 world = parent * local_transform(doc, node);
    if (node.contains("mesh")) {
      for (const json& primitive : doc.item("meshes", node.at("mesh")).at("primitives")) {
        add_primitive(doc, primitive, world, model.mesh);
        const std::int64_t gltf_material = primitive.value("material", std::int64_t{-1});
        model.mesh.materials.resize(model.mesh.triangles.size(), model_material(doc, gltf_material, known, model.materials));
      }
    }
    if (node.contains("children")) {
      const json& children = node.at("children");
      for (auto child = children.rbegin(); child != children.rend(); ++child) stack.emplace_back(*child, world);
    }
  }
}

/// Root nodes to draw: the default scene, else scene 0, else every node that is nobody's child.
std::vector<json> root_nodes(const GltfDocument& doc) {
  const json& scenes = doc.array("scenes");
  if (!scenes.empty()) {
    const json& scene = doc.item("scenes", doc.root().value("scene", json(0)));
    return scene.value("nodes", std::vector<json>{});
  }
  const json& nodes = doc.array("nodes");
  std::vector<bool> is_child(nodes.size(), false);
  for (const json& node : nodes) {
    for (const json& child : node.value("children", std::vector<json>{})) {
      const std::size_t c = child.get<std::size_t>();
      if (c < is_child.size()) is_child[c] = true;
    }
  }
  std::vector<json> roots;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (!is_child[i]) roots.emplace_back(i);
  }
  return roots;
}

/// Splits a .glb container into its JSON text and binary chunk.
std::pair<std::string_view, std::string_view> split_glb(const std::string& name, std::string_view bytes) {
  if (bytes.size() < 20 || bytes.substr(0, 4) != "glTF") throw InputError(name + ": not a GLB file (bad magic)");
  if (u32_le(bytes, 4) != 2) throw InputError(name + ": unsupported GLB version " + std::to_string(u32_le(bytes, 4)));
  const std::uint32_t total = u32_le(bytes, 8);
  if (total > bytes.size()) throw InputError(name + ": file is truncated (GLB header says " + std::to_string(total) + " bytes)");
  std::string_view json_chunk;
  std::string_view binary_chunk;
  std::size_t offset = 12;
  while (offset + 8 <= total) {
    const std::uint32_t length = u32_le(bytes, offset);
    const std::uint32_t type = u32_le(bytes, offset + 4);
    if (length > total - offset - 8) throw InputError(name + ": file is truncated (GLB chunk exceeds the file)");
    const std::string_view data = bytes.substr(offset + 8, length);
    if (type == 0x4E4F534Au && json_chunk.data() == nullptr) json_chunk = data;
    if (type == 0x004E4942u && binary_chunk.data() == nullptr) binary_chunk = data;
    offset += 8 + static_cast<std::size_t>(length);
  }
  if (json_chunk.data() == nullptr) throw InputError(name + ": GLB has no JSON chunk");
  return {json_chunk, binary_chunk};
}

}  // namespace

Model read_gltf(const std::filesystem::path& path, std::string_view bytes, bool binary) {
  const std::string name = path.string();
  std::string_view text = bytes;
  std::string_view glb_binary;
  if (binary) std::tie(text, glb_binary) = split_glb(name, bytes);
  json document = json::parse(text.begin(), text.end(), nullptr, false);
  if (document.is_discarded() || !document.is_object()) throw InputError(name + ": invalid glTF JSON");
  Model model;
  try {
    const GltfDocument doc(path, std::move(document), glb_binary);
    const std::string version = doc.root().at("asset").at("version").get<std::string>();
    if (version.rfind("2.", 0) != 0) doc.fail("unsupported glTF version " + version);
    std::vector<bool> visited(doc.array("nodes").size(), false);
    std::map<std::int64_t, std::uint32_t> known;
    for (const json& root : root_nodes(doc)) add_hierarchy(doc, root, visited, known, model);
    // A file whose primitives name no material has none (not one "default" for everything).
    const bool any_named = !known.empty() && known.rbegin()->first >= 0;  // keys ascend; -1 = none
    if (!any_named) {
      model.materials.clear();
      model.mesh.materials.clear();
    }
  } catch (const nlohmann::json::exception& error) {
    throw InputError(name + ": malformed glTF (" + error.what() + ")");
  }
  return model;
}

}  // namespace dg::detail
