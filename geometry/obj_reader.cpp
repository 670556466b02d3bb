// Wavefront OBJ reader: positions, polygon faces and their materials (usemtl, with colours from
// the mtllib files); everything else is skipped.

#include "geometry/model_reader.h"
#include "geometry/text_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <vector>

namespace dg::detail {

namespace {

/// Resolves one face corner token ("7", "7/2", "7//3", "-1/2/3") to a 0-based position index.
/// Positive indices may refer forward; they are range-checked once the whole file is read.
std::int64_t resolve_corner(const std::string& name, std::size_t line, std::string_view token,
                            std::size_t vertex_count) {
  const std::size_t slash = token.find('/');
  std::int64_t index = 0;
  if (!parse_number(token.substr(0, slash), index)) {
    throw_line_error(name, line, "malformed face corner '" + std::string(token) + "'");
  }
  if (index == 0) throw_line_error(name, line, "face index 0 (OBJ indices start at 1)");
  if (index > 0) return index - 1;
  const std::int64_t resolved = static_cast<std::int64_t>(vertex_count) + index;
  if (resolved < 0) {
    throw_line_error(name, line, "relative face index " + std::to_string(index) + " points before the first vertex");
  }
  return resolved;
}

/// The rest of a line without leading and trailing blanks (material and file names may hold spaces).
std::string_view trimmed(std::string_view rest) {
  skip_blanks(rest);
  while (!rest.empty() && is_blank(rest.back())) rest.remove_suffix(1);
  return rest;
}

/// Fills the colours of `materials` from the `newmtl`, `Kd r g b` and `d` (or `Tr`) entries of one
/// MTL file.
/// A library that cannot be read leaves the default colours: the geometry does not depend on it.
void read_material_colours(const std::filesystem::path& library, std::vector<Material>& materials) {
  std::ifstream in(library, std::ios::binary);
  if (!in) return;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  LineReader reader(text);
  std::string_view line;
  Material* current = nullptr;
  while (reader.next(line)) {
    std::string_view rest = line;
    const std::string_view keyword = next_token(rest);
    if (keyword == "newmtl") {
      const std::string_view name = trimmed(rest);
      current = nullptr;
      for (Material& material : materials)
        if (material.name == name) current = &material;
    } else if ((keyword == "d" || keyword == "Tr") && current) {
      double value = 0.0;
      if (read_number(rest, value) && std::isfinite(value))
        current->opacity = std::clamp(keyword == "d" ? value : 1.0 - value, 0.0, 1.0);
    } else if (keyword == "Kd" && current) {
      Vec3 kd;
      if (read_number(rest, kd.x()) && read_number(rest, kd.y()) && read_number(rest, kd.z()) && kd.allFinite())
        current->diffuse = kd.cwiseMax(0.0).cwiseMin(1.0);
    }
  }
}

}  // namespace

Model read_obj(const std::filesystem::path& path, std::string_view text) {
  const std::string name = path.string();
  Model model;
  TriangleMesh& mesh = model.mesh;
  mesh.positions.reserve(text.size() / 64);
  mesh.triangles.reserve(text.size() / 64);
  std::vector<std::uint32_t> corners;
  PolygonFaces polygons;
  std::int64_t max_index = -1;
  std::size_t max_index_line = 0;
  std::map<std::string, std::uint32_t, std::less<>> material_index;  // name -> index in model.materials
  std::uint32_t material = 0;  // current usemtl; faces before the first one get "default" (index 0)
  std::vector<std::string> libraries;

  LineReader reader(text, true);
  std::string_view line;
  while (reader.next(line)) {
    std::string_view rest = line;
    const std::string_view keyword = next_token(rest);
    if (keyword == "v") {
      Vec3 p;
      if (!read_number(rest, p.x()) || !read_number(rest, p.y()) || !read_number(rest, p.z())) {
        throw_line_error(name, reader.line(), "malformed vertex (expected 'v x y z')");
      }
      mesh.positions.push_back(p);
    } else if (keyword == "f") {
      corners.clear();
      for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest)) {
        const std::int64_t index = resolve_corner(name, reader.line(), token, mesh.positions.size());
        if (index > std::numeric_limits<std::uint32_t>::max() - 1) {
          throw_line_error(name, reader.line(), "face index " + std::string(token) + " out of range");
        }
        if (index > max_index) {
          max_index = index;
          max_index_line = reader.line();
        }
        corners.push_back(static_cast<std::uint32_t>(index));
      }
      if (corners.size() < 3) throw_line_error(name, reader.line(), "face with fewer than 3 corners");
      add_polygon(mesh, corners.data(), corners.size(), polygons);
      if (!model.materials.empty()) mesh.materials.resize(mesh.triangles.size(), material);
    } else if (keyword == "usemtl") {
      if (model.materials.empty() && !mesh.triangles.empty()) {  // faces came before any usemtl
        model.materials.push_back({"default"});
        material_index.emplace("default", 0);
        mesh.materials.assign(mesh.triangles.size(), 0);
      }
      const std::string_view material_name = trimmed(rest);
      auto found = material_index.find(material_name);
      if (found == material_index.end()) {
        found = material_index.emplace(std::string(material_name), static_cast<std::uint32_t>(model.materials.size())).first;
        model.materials.push_back({found->first});
      }
      material = found->second;
    } else if (keyword == "mtllib") {
      for (std::string_view file = next_token(rest); !file.empty(); file = next_token(rest)) libraries.emplace_back(file);
    }
    // Comments, vt/vn/vp, groups, objects, smoothing, lines and points are skipped.
  }
  for (const std::string& library : libraries) read_material_colours(path.parent_path() / library, model.materials);
  if (max_index >= static_cast<std::int64_t>(mesh.positions.size())) {
    throw_line_error(name, max_index_line,
                     "face index " + std::to_string(max_index + 1) + " out of range (file has " +
                         std::to_string(mesh.positions.size()) + " vertices)");
  }
  triangulate_polygons(mesh, polygons);
  return model;
}

}  // namespace dg::detail
