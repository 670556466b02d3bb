// OBJ writer: positions with shortest round-trip decimals (std::to_chars), 1-based faces, and
// the MTL file that names its materials.

#include "geometry/mesh_writer.h"

#include <cctype>
#include <charconv>
#include <set>
#include <string>

namespace dg::detail {

namespace {

void append_number(std::string& text, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  text.append(buffer, result.ptr);
}

void append_number(std::string& text, std::uint64_t value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  text.append(buffer, result.ptr);
}

// Appends `keyword` `value` and a line end (pieces appended one by one: GCC 12 warns wrongly
// about operator+ chains of strings and characters).
void append_line(std::string& text, const char* keyword, const std::string& value) {
  text += keyword;
  text += value;
  text += '\n';
}

}  // namespace

void write_obj(std::ostream& out, const TriangleMesh& mesh, const ObjMaterials* materials) {
  std::string text = "# dockgrammar\n";
  text.reserve(mesh.positions.size() * 40 + mesh.triangles.size() * 24 + 64);
  if (materials) append_line(text, "mtllib ", materials->library);
  for (const Vec3& p : mesh.positions) {
    text += 'v';
    for (int axis = 0; axis < 3; ++axis) {
      text += ' ';
      append_number(text, p[axis]);
    }
    text += '\n';
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (materials && (t == 0 || mesh.materials[t] != mesh.materials[t - 1]))
      append_line(text, "usemtl ", materials->names[mesh.materials[t]]);
    text += 'f';
    for (std::uint32_t index : mesh.triangles[t]) {
      text += ' ';
      append_number(text, std::uint64_t{index} + 1);
    }
    text += '\n';
  }
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

std::vector<std::string> obj_material_names(const std::vector<Material>& materials) {
  std::vector<std::string> names;
  std::set<std::string> used;
  for (std::size_t i = 0; i < materials.size(); ++i) {
    std::string name = materials[i].name;
    for (char& c : name)
      if (std::isspace(static_cast<unsigned char>(c))) c = '_';
    if (name.empty()) name = "material_" + std::to_string(i);
    const std::string suffix = std::to_string(i);
    while (used.contains(name)) {
      name += '_';
      name += suffix;
    }
    used.insert(name);
    names.push_back(std::move(name));
  }
  return names;
}

void write_mtl(std::ostream& out, const std::vector<Material>& materials, const std::vector<std::string>& names) {
  std::string text = "# dockgrammar\n";
  for (std::size_t i = 0; i < materials.size(); ++i) {
    text += '\n';
    append_line(text, "newmtl ", names[i]);
    text += "Kd";
    for (int channel = 0; channel < 3; ++channel) {
      text += ' ';
      append_number(text, materials[i].diffuse[channel]);
    }
    text += '\n';
    if (materials[i].opacity < 1.0) {
      text += "d ";
      append_number(text, materials[i].opacity);
      text += '\n';
    }
  }
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

}  // namespace dg::detail
