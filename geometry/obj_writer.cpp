// OBJ writer: positions with shortest round-trip decimals (std::to_chars), 1-based faces.

#include "geometry/mesh_writer.h"

#include <charconv>
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

}  // namespace

void write_obj(std::ostream& out, const TriangleMesh& mesh) {
  std::string text = "# dockgrammar\n";
  text.reserve(mesh.positions.size() * 40 + mesh.triangles.size() * 24 + 64);
  for (const Vec3& p : mesh.positions) {
    text += 'v';
    for (int axis = 0; axis < 3; ++axis) {
      text += ' ';
      append_number(text, p[axis]);
    }
    text += '\n';
  }
  for (const Triangle& t : mesh.triangles) {
    text += 'f';
    for (std::uint32_t index : t) {
      text += ' ';
      append_number(text, std::uint64_t{index} + 1);
    }
    text += '\n';
  }
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

}  // namespace dg::detail
