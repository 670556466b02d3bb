// PLY reader: ascii, binary_little_endian and binary_big_endian; any property types.
// The "vertex" element gives positions (x, y, z) and optional normals (nx, ny, nz); the "face"
// element's "vertex_indices" (or "vertex_index") list gives polygons. Other elements are skipped.

#include "geometry/model_reader.h"
#include "geometry/text_reader.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

namespace dg::detail {

namespace {

enum class PlyFormat { ascii, binary_little_endian, binary_big_endian };
enum class ScalarType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

struct PlyProperty {
  std::string name;
  ScalarType type = ScalarType::float32;  ///< item type for lists
  bool is_list = false;
  ScalarType count_type = ScalarType::uint8;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  PlyFormat format = PlyFormat::ascii;
  std::vector<PlyElement> elements;
  std::size_t body_offset = 0;
  std::size_t body_line = 0;  ///< line number of the first body line (ascii)
};

std::optional<ScalarType> parse_type(std::string_view word) {
  if (word == "char" || word == "int8") return ScalarType::int8;
  if (word == "uchar" || word == "uint8") return ScalarType::uint8;
  if (word == "short" || word == "int16") return ScalarType::int16;
  if (word == "ushort" || word == "uint16") return ScalarType::uint16;
  if (word == "int" || word == "int32") return ScalarType::int32;
  if (word == "uint" || word == "uint32") return ScalarType::uint32;
  if (word == "float" || word == "float32") return ScalarType::float32;
  if (word == "double" || word == "float64") return ScalarType::float64;
  return std::nullopt;
}

std::size_t type_size(ScalarType type) {
  switch (type) {
    case ScalarType::int8:
    case ScalarType::uint8:
      return 1;
    case ScalarType::int16:
    case ScalarType::uint16:
      return 2;
    case ScalarType::int32:
    case ScalarType::uint32:
    case ScalarType::float32:
      return 4;
    case ScalarType::float64:
      return 8;
  }
  return 0;
}

ScalarType parse_type_or_throw(const std::string& name, std::size_t line, std::string_view word) {
  const std::optional<ScalarType> type = parse_type(word);
  if (!type) throw_line_error(name, line, "unknown property type '" + std::string(word) + "'");
  return *type;
}

PlyHeader parse_header(const std::string& name, std::string_view bytes) {
  LineReader reader(bytes);
  std::string_view line;
  if (!reader.next(line) || line != "ply") throw InputError(name + ": not a PLY file (missing 'ply' magic line)");
  PlyHeader header;
  bool has_format = false;
  while (true) {
    if (!reader.next(line)) throw InputError(name + ": PLY header has no end_header line");
    std::string_view rest = line;
    const std::string_view keyword = next_token(rest);
    const std::size_t n = reader.line();
    if (keyword == "end_header") break;
    if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "format") {
      const std::string_view format = next_token(rest);
      if (format == "ascii") {
        header.format = PlyFormat::ascii;
      } else if (format == "binary_little_endian") {
        header.format = PlyFormat::binary_little_endian;
      } else if (format == "binary_big_endian") {
        header.format = PlyFormat::binary_big_endian;
      } else {
        throw_line_error(name, n, "unknown PLY format '" + std::string(format) + "'");
      }
      has_format = true;
    } else if (keyword == "element") {
      PlyElement element;
      element.name = std::string(next_token(rest));
      if (element.name.empty() || !read_number(rest, element.count)) {
        throw_line_error(name, n, "malformed element line (expected 'element <name> <count>')");
      }
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) throw_line_error(name, n, "property before any element");
      PlyProperty property;
      const std::string_view type = next_token(rest);
      if (type == "list") {
        property.is_list = true;
        property.count_type = parse_type_or_throw(name, n, next_token(rest));
        if (property.count_type == ScalarType::float32 || property.count_type == ScalarType::float64) {
          throw_line_error(name, n, "list count type must be an integer type");
        }
        property.type = parse_type_or_throw(name, n, next_token(rest));
      } else {
        property.type = parse_type_or_throw(name, n, type);
      }
      property.name = std::string(next_token(rest));
      if (property.name.empty()) throw_line_error(name, n, "property without a name");
      header.elements.back().properties.push_back(std::move(property));
    } else {
      throw_line_error(name, n, "unknown PLY header keyword '" + std::string(keyword) + "'");
    }
  }
  if (!has_format) throw InputError(name + ": PLY header has no format line");
  header.body_offset = reader.offset();
  header.body_line = reader.line() + 1;
  return header;
}

/// Reads scalar values from the body, in ascii or binary form, with bounds checks.
class BodyReader {
 public:
  BodyReader(const std::string& name, std::string_view body, PlyFormat format, std::size_t first_line)
      : name_(name), body_(body), format_(format), line_(first_line) {}

  /// Reads one value of `type` as a double (integers up to 32 bits convert exactly).
  double read(ScalarType type) {
    if (format_ == PlyFormat::ascii) return read_ascii(type);
    const std::size_t size = type_size(type);
    if (body_.size() - pos_ < size) throw InputError(name_ + ": file is truncated (binary PLY data ends early)");
    unsigned char raw[8];
    std::memcpy(raw, body_.data() + pos_, size);
    pos_ += size;
    const bool file_little = format_ == PlyFormat::binary_little_endian;
    if (file_little != (std::endian::native == std::endian::little)) std::reverse(raw, raw + size);
    switch (type) {
      case ScalarType::int8: return decode<std::int8_t>(raw);
      case ScalarType::uint8: return decode<std::uint8_t>(raw);
      case ScalarType::int16: return decode<std::int16_t>(raw);
      case ScalarType::uint16: return decode<std::uint16_t>(raw);
      case ScalarType::int32: return decode<std::int32_t>(raw);
      case ScalarType::uint32: return decode<std::uint32_t>(raw);
      case ScalarType::float32: return static_cast<double>(decode<float>(raw));
      case ScalarType::float64: return decode<double>(raw);
    }
    return 0.0;
  }

  /// Bytes not yet read.
  std::size_t remaining() const { return body_.size() - pos_; }
  /// Current line (ascii) for messages.
  std::size_t line() const { return line_; }
  bool ascii() const { return format_ == PlyFormat::ascii; }

 private:
  template <typename T>
  static double decode(const unsigned char* raw) {
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return static_cast<double>(value);
  }

  double read_ascii(ScalarType type) {
    while (pos_ < body_.size() && std::isspace(static_cast<unsigned char>(body_[pos_]))) {
      if (body_[pos_] == '\n') ++line_;
      ++pos_;
    }
    std::size_t end = pos_;
    while (end < body_.size() && !std::isspace(static_cast<unsigned char>(body_[end]))) ++end;
    const std::string_view token = body_.substr(pos_, end - pos_);
    if (token.empty()) throw InputError(name_ + ": file is truncated (ascii PLY data ends early)");
    pos_ = end;
    double value = 0.0;
    if (type == ScalarType::float32 || type == ScalarType::float64) {
      if (parse_number(token, value)) return value;
    } else {
      std::int64_t integer = 0;
      if (parse_number(token, integer)) return static_cast<double>(integer);
    }
    throw_line_error(name_, line_, "malformed value '" + std::string(token.substr(0, 40)) + "'");
  }

  const std::string& name_;
  std::string_view body_;
  PlyFormat format_;
  std::size_t pos_ = 0;
  std::size_t line_;
};

/// Smallest number of bytes one instance of `element` can take in the file.
std::size_t min_instance_size(const PlyElement& element, bool ascii) {
  std::size_t size = 0;
  for (const PlyProperty& p : element.properties) size += ascii ? 2 : type_size(p.is_list ? p.count_type : p.type);
  return size;
}

/// Reads a list length or vertex index: a non-negative integer that fits 32 bits.
std::uint64_t read_integer(BodyReader& body, ScalarType type, const std::string& name, const char* what) {
  const double value = body.read(type);
  if (!(value >= 0.0) || value != std::floor(value) || value > 4294967295.0) {
    throw InputError(name + ": invalid " + what + " " + format_number(value) +
                     (body.ascii() ? " at line " + std::to_string(body.line()) : std::string()));
  }
  return static_cast<std::uint64_t>(value);
}

std::optional<std::size_t> find_property(const PlyElement& element, std::string_view property) {
  for (std::size_t i = 0; i < element.properties.size(); ++i) {
    if (element.properties[i].name == property) return i;
  }
  return std::nullopt;
}

}  // namespace

Model read_ply(const std::string& name, std::string_view bytes) {
  const PlyHeader header = parse_header(name, bytes);
  BodyReader body(name, bytes.substr(header.body_offset), header.format, header.body_line);
  const bool ascii = header.format == PlyFormat::ascii;

  Model model;
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;
  std::vector<std::uint32_t> corners;
  PolygonFaces polygons;
  bool seen_vertices = false;
  bool has_faces = false;
  std::uint64_t vertex_count = 0;

  for (const PlyElement& element : header.elements) {
    if (element.count == 0) continue;
    const std::size_t min_size = min_instance_size(element, ascii);
    if (min_size == 0) continue;  // no properties: nothing stored in the body
    if (element.count > body.remaining() / min_size) {
      throw InputError(name + ": header claims " + std::to_string(element.count) + " " + element.name +
                       " elements but only " + std::to_string(body.remaining()) + " bytes follow");
    }
    if (element.name == "vertex" && !seen_vertices) {
      seen_vertices = true;
      std::vector<double> scalars(element.properties.size(), 0.0);
      const auto x = find_property(element, "x"), y = find_property(element, "y"), z = find_property(element, "z");
      if (!x || !y || !z) throw InputError(name + ": vertex element lacks x, y or z");
      const auto nx = find_property(element, "nx"), ny = find_property(element, "ny"),
                 nz = find_property(element, "nz");
      const bool with_normals = nx && ny && nz;
      vertex_count = element.count;
      positions.reserve(element.count);
      if (with_normals) normals.reserve(element.count);
      for (std::uint64_t i = 0; i < element.count; ++i) {
        for (std::size_t k = 0; k < element.properties.size(); ++k) {
          const PlyProperty& p = element.properties[k];
          if (!p.is_list) {
            scalars[k] = body.read(p.type);
            continue;
          }
          const std::uint64_t n = read_integer(body, p.count_type, name, "list length");
          for (std::uint64_t j = 0; j < n; ++j) body.read(p.type);
        }
        positions.emplace_back(scalars[*x], scalars[*y], scalars[*z]);
        if (with_normals) normals.emplace_back(scalars[*nx], scalars[*ny], scalars[*nz]);
      }
      continue;
    }

    std::optional<std::size_t> list;
    if (element.name == "face") {
      list = find_property(element, "vertex_indices");
      if (!list) list = find_property(element, "vertex_index");
      if (!list || !element.properties[*list].is_list) {
        throw InputError(name + ": face element lacks a vertex_indices list");
      }
      has_faces = true;
      model.mesh.triangles.reserve(element.count);
    }
    for (std::uint64_t i = 0; i < element.count; ++i) {
      for (std::size_t k = 0; k < element.properties.size(); ++k) {
        const PlyProperty& p = element.properties[k];
        if (!p.is_list) {
          body.read(p.type);
          continue;
        }
        const std::uint64_t n = read_integer(body, p.count_type, name, "list length");
        if (n > body.remaining() / (ascii ? 1 : type_size(p.type))) {
          throw InputError(name + ": file is truncated (list of " + std::to_string(n) + " items)");
        }
        if (!list || k != *list) {
          for (std::uint64_t j = 0; j < n; ++j) body.read(p.type);
          continue;
        }
        if (n < 3) throw InputError(name + ": face " + std::to_string(i) + " has fewer than 3 corners");
        corners.clear();
        for (std::uint64_t j = 0; j < n; ++j) {
          corners.push_back(static_cast<std::uint32_t>(read_integer(body, p.type, name, "vertex index")));
        }
        add_polygon(model.mesh, corners.data(), corners.size(), polygons);
      }
    }
  }

  for (const Triangle& t : model.mesh.triangles) {
    for (std::uint32_t index : t) {
      if (index >= vertex_count) {
        throw InputError(name + ": face index " + std::to_string(index) + " out of range (file has " +
                         std::to_string(vertex_count) + " vertices)");
      }
    }
  }
  if (has_faces && !model.mesh.triangles.empty()) {
    model.mesh.positions = std::move(positions);
    triangulate_polygons(model.mesh, polygons);
  } else {
    model.cloud.positions = std::move(positions);
    model.cloud.normals = std::move(normals);
  }
  return model;
}

}  // namespace dg::detail
