// PLY writer: binary little endian, double coordinates, optional uchar vertex and face colours.

#include "geometry/mesh_writer.h"

#include <cstdint>
#include <string>

namespace dg::detail {

void write_ply(std::ostream& out, const TriangleMesh& mesh, const std::vector<Rgb>* colors,
               const std::vector<Rgb>* face_colors) {
  const std::string rgb = "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  std::string bytes = "ply\nformat binary_little_endian 1.0\ncomment dockgrammar\nelement vertex " +
                      std::to_string(mesh.positions.size()) +
                      "\nproperty double x\nproperty double y\nproperty double z\n";
  if (colors) bytes += rgb;
  bytes += "element face " + std::to_string(mesh.triangles.size()) + "\nproperty list uchar uint vertex_indices\n";
  if (face_colors) bytes += rgb;
  bytes += "end_header\n";
  bytes.reserve(bytes.size() + mesh.positions.size() * 27 + mesh.triangles.size() * 16);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    for (int axis = 0; axis < 3; ++axis) append_le(bytes, mesh.positions[i][axis]);
    if (colors) {
      for (std::uint8_t channel : (*colors)[i]) bytes.push_back(static_cast<char>(channel));
    }
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    bytes.push_back(3);
    for (std::uint32_t index : mesh.triangles[t]) append_le(bytes, index);
    if (face_colors) {
      for (std::uint8_t channel : (*face_colors)[t]) bytes.push_back(static_cast<char>(channel));
    }
  }
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

void write_ply_points(std::ostream& out, const PointCloud& cloud, const std::vector<Rgb>* colors) {
  const bool normals = cloud.has_normals();
  std::string bytes = "ply\nformat binary_little_endian 1.0\ncomment dockgrammar\nelement vertex " +
                      std::to_string(cloud.positions.size()) + "\nproperty double x\nproperty double y\nproperty double z\n";
  if (normals) bytes += "property double nx\nproperty double ny\nproperty double nz\n";
  if (colors) bytes += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  bytes += "end_header\n";
  bytes.reserve(bytes.size() + cloud.positions.size() * (normals ? 51 : 27));
  for (std::size_t i = 0; i < cloud.positions.size(); ++i) {
    for (int axis = 0; axis < 3; ++axis) append_le(bytes, cloud.positions[i][axis]);
    if (normals)
      for (int axis = 0; axis < 3; ++axis) append_le(bytes, cloud.normals[i][axis]);
    if (colors)
      for (std::uint8_t channel : (*colors)[i]) bytes.push_back(static_cast<char>(channel));
  }
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace dg::detail
