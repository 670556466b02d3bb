// OFF reader: "OFF" header (optionally with C/N/ST prefixes), counts, vertex lines, polygon lines.

#include "geometry/model_reader.h"
#include "geometry/text_reader.h"

#include <cstdint>
#include <vector>

namespace dg::detail {

namespace {

/// Next line with content, comments ('#' to the end of the line) removed; false at the end.
bool next_content_line(LineReader& reader, std::string_view& line) {
  while (reader.next(line)) {
    const std::size_t hash = line.find('#');
    if (hash != std::string_view::npos) line = line.substr(0, hash);
    std::string_view probe = line;
    if (!next_token(probe).empty()) return true;
  }
  return false;
}

}  // namespace

Model read_off(const std::string& name, std::string_view text) {
  LineReader reader(text);
  std::string_view line;
  if (!next_content_line(reader, line)) throw InputError(name + ": empty file");
  std::string_view rest = line;
  const std::string_view header = next_token(rest);
  if (header.size() < 3 || header.substr(header.size() - 3) != "OFF") {
    throw InputError(name + ": not an OFF file (first word is '" + std::string(header.substr(0, 40)) + "')");
  }
  const std::string_view prefix = header.substr(0, header.size() - 3);
  if (prefix != "" && prefix != "C" && prefix != "N" && prefix != "CN" && prefix != "NC" && prefix != "ST" &&
      prefix != "STC" && prefix != "STN" && prefix != "STCN") {
    throw InputError(name + ": unsupported OFF variant '" + std::string(header) + "'");
  }
  std::string_view probe = rest;
  if (next_token(probe) == "BINARY") throw InputError(name + ": binary OFF is not supported");
  if (next_token(probe).empty()) {
    if (!next_content_line(reader, line)) throw InputError(name + ": missing vertex and face counts");
    rest = line;
  }
  std::uint64_t vertex_count = 0;
  std::uint64_t face_count = 0;
  if (!read_number(rest, vertex_count) || !read_number(rest, face_count)) {
    throw_line_error(name, reader.line(), "malformed counts (expected 'vertices faces edges')");
  }
  const std::uint64_t remaining = text.size() - reader.offset();
  if (vertex_count > remaining / 6 + 1 || face_count > remaining / 6 + 1) {
    throw InputError(name + ": header claims " + std::to_string(vertex_count) + " vertices and " +
                     std::to_string(face_count) + " faces but only " + std::to_string(remaining) +
                     " bytes follow");
  }

  Model model;
  TriangleMesh& mesh = model.mesh;
  mesh.positions.reserve(vertex_count);
  mesh.triangles.reserve(face_count);
  for (std::uint64_t i = 0; i < vertex_count; ++i) {
    if (!next_content_line(reader, line)) {
      throw InputError(name + ": file ends after " + std::to_string(i) + " of " + std::to_string(vertex_count) +
                       " vertices");
    }
    rest = line;
    Vec3 p;
    if (!read_number(rest, p.x()) || !read_number(rest, p.y()) || !read_number(rest, p.z())) {
      throw_line_error(name, reader.line(), "malformed vertex (expected 'x y z')");
    }
    mesh.positions.push_back(p);
  }
  std::vector<std::uint32_t> corners;
  PolygonFaces polygons;
  for (std::uint64_t f = 0; f < face_count; ++f) {
    if (!next_content_line(reader, line)) {
      throw InputError(name + ": file ends after " + std::to_string(f) + " of " + std::to_string(face_count) +
                       " faces");
    }
    rest = line;
    std::uint64_t count = 0;
    if (!read_number(rest, count)) throw_line_error(name, reader.line(), "malformed face (expected 'n i1 ... in')");
    if (count < 3) throw_line_error(name, reader.line(), "face with fewer than 3 corners");
    if (count > line.size()) throw_line_error(name, reader.line(), "face claims more corners than the line holds");
    corners.clear();
    for (std::uint64_t k = 0; k < count; ++k) {
      std::uint64_t index = 0;
      if (!read_number(rest, index)) throw_line_error(name, reader.line(), "malformed or missing face index");
      if (index >= vertex_count) {
        throw_line_error(name, reader.line(),
                         "face index " + std::to_string(index) + " out of range (file has " +
                             std::to_string(vertex_count) + " vertices)");
      }
      corners.push_back(static_cast<std::uint32_t>(index));
    }
    add_polygon(mesh, corners.data(), corners.size(), polygons);
  }
  triangulate_polygons(mesh, polygons);
  return model;
}

}  // namespace dg::detail
