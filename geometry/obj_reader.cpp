// Wavefront OBJ reader: positions and polygon faces; everything else is skipped.

#include "geometry/model_reader.h"
#include "geometry/text_reader.h"

#include <cstdint>
#include <limits>
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

}  // namespace

Model read_obj(const std::string& name, std::string_view text) {
  Model model;
  TriangleMesh& mesh = model.mesh;
  mesh.positions.reserve(text.size() / 64);
  mesh.triangles.reserve(text.size() / 64);
  std::vector<std::uint32_t> corners;
  std::int64_t max_index = -1;
  std::size_t max_index_line = 0;

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
      add_fan(mesh, corners.data(), corners.size());
    }
    // Comments, vt/vn/vp, groups, objects, smoothing, materials, lines and points are skipped.
  }
  if (max_index >= static_cast<std::int64_t>(mesh.positions.size())) {
    throw_line_error(name, max_index_line,
                     "face index " + std::to_string(max_index + 1) + " out of range (file has " +
                         std::to_string(mesh.positions.size()) + " vertices)");
  }
  return model;
}

}  // namespace dg::detail
