// STL reader. Binary STL is recognised by its size (84 + 50 * triangle count bytes), not by
// the "solid" prefix, which many binary exporters also write. The result is a triangle soup:
// three new positions per facet (clean_mesh welds them).

#include "geometry/model_reader.h"
#include "geometry/text_reader.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <vector>

namespace dg::detail {

namespace {

constexpr std::size_t binary_header_size = 84;
constexpr std::size_t binary_facet_size = 50;

std::uint32_t read_u32_le(const char* p) {
  unsigned char b[4];
  std::memcpy(b, p, 4);
  return static_cast<std::uint32_t>(b[0]) | (static_cast<std::uint32_t>(b[1]) << 8) |
         (static_cast<std::uint32_t>(b[2]) << 16) | (static_cast<std::uint32_t>(b[3]) << 24);
}

float read_f32_le(const char* p) { return std::bit_cast<float>(read_u32_le(p)); }

Model read_binary(std::string_view bytes, std::uint32_t facets) {
  Model model;
  TriangleMesh& mesh = model.mesh;
  mesh.positions.reserve(3 * static_cast<std::size_t>(facets));
  mesh.triangles.reserve(facets);
  const char* p = bytes.data() + binary_header_size;
  for (std::uint32_t f = 0; f < facets; ++f, p += binary_facet_size) {
    const auto first = static_cast<std::uint32_t>(mesh.positions.size());
    for (int corner = 0; corner < 3; ++corner) {
      const char* v = p + 12 + 12 * corner;  // skip the facet normal
      mesh.positions.emplace_back(read_f32_le(v), read_f32_le(v + 4), read_f32_le(v + 8));
    }
    mesh.triangles.push_back({first, first + 1, first + 2});
  }
  return model;
}

Model read_ascii(const std::string& name, std::string_view text) {
  Model model;
  TriangleMesh& mesh = model.mesh;
  std::vector<std::uint32_t> loop;
  PolygonFaces polygons;
  bool in_loop = false;
  LineReader reader(text);
  std::string_view line;
  while (reader.next(line)) {
    std::string_view rest = line;
    const std::string_view keyword = next_token(rest);
    if (keyword == "vertex") {
      if (!in_loop) throw_line_error(name, reader.line(), "vertex outside 'outer loop'");
      Vec3 p;
      if (!read_number(rest, p.x()) || !read_number(rest, p.y()) || !read_number(rest, p.z())) {
        throw_line_error(name, reader.line(), "malformed vertex (expected 'vertex x y z')");
      }
      loop.push_back(static_cast<std::uint32_t>(mesh.positions.size()));
      mesh.positions.push_back(p);
    } else if (keyword == "outer") {
      in_loop = true;
      loop.clear();
    } else if (keyword == "endloop") {
      if (!in_loop) throw_line_error(name, reader.line(), "endloop without 'outer loop'");
      if (loop.size() < 3) throw_line_error(name, reader.line(), "facet with fewer than 3 vertices");
      add_polygon(mesh, loop.data(), loop.size(), polygons);
      in_loop = false;
    } else if (keyword.empty() || keyword == "solid" || keyword == "endsolid" || keyword == "facet" ||
               keyword == "endfacet") {
      continue;
    } else {
      throw_line_error(name, reader.line(), "unexpected '" + std::string(keyword.substr(0, 40)) + "' in ascii STL");
    }
  }
  if (in_loop) throw InputError(name + ": file is truncated (facet without endloop)");
  triangulate_polygons(mesh, polygons);
  return model;
}

}  // namespace

Model read_stl(const std::string& name, std::string_view bytes) {
  if (bytes.size() >= binary_header_size) {
    const std::uint32_t facets = read_u32_le(bytes.data() + 80);
    const std::uint64_t expected = binary_header_size + binary_facet_size * static_cast<std::uint64_t>(facets);
    if (expected == bytes.size()) return read_binary(bytes, facets);
  }
  std::string_view probe = bytes.substr(0, 512);
  skip_blanks(probe);
  while (!probe.empty() && (probe.front() == '\n' || probe.front() == '\r')) probe.remove_prefix(1);
  if (probe.substr(0, 5) == "solid") {
    const bool text = std::none_of(probe.begin(), probe.end(), [](char c) { return c == '\0'; });
    if (text) return read_ascii(name, bytes);
  }
  if (bytes.size() < binary_header_size) throw InputError(name + ": file is too short for a binary STL");
  const std::uint32_t facets = read_u32_le(bytes.data() + 80);
  throw InputError(name + ": binary STL size mismatch: header says " + std::to_string(facets) + " triangles (" +
                   std::to_string(binary_header_size + binary_facet_size * static_cast<std::uint64_t>(facets)) +
                   " bytes) but the file has " + std::to_string(bytes.size()) + " bytes");
}

}  // namespace dg::detail
