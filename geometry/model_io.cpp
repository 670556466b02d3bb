// read_model / write_mesh: choose the format by extension, load the file, check the result.

#include "geometry/model_io.h"

#include "geometry/atomic_file.h"
#include "geometry/errors.h"
#include "geometry/mesh_writer.h"
#include "geometry/model_reader.h"
#include "geometry/text_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

namespace dg {

std::string lower_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

namespace {

/// Largest absolute coordinate accepted from a file (beyond it double precision is too coarse
/// for the tolerances the pipeline uses).
constexpr double max_coordinate = 1e15;

/// Whole file as bytes; InputError when it is missing, a folder, unreadable or empty.
std::string load_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status)) throw InputError(name + ": no such file");
  if (std::filesystem::is_directory(status)) throw InputError(name + ": is a folder, not a model file");
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw InputError(name + ": cannot open for reading");
  const std::streamoff size = in.tellg();
  if (size < 0) throw InputError(name + ": cannot determine the file size");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.seekg(0);
  if (!in.read(bytes.data(), size)) throw InputError(name + ": read error");
  if (bytes.empty()) throw InputError(name + ": empty file");
  return bytes;
}

/// Throws unless every coordinate is finite and within +-max_coordinate.
void check_coordinates(const std::string& name, const std::vector<Vec3>& points, const char* what) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (int axis = 0; axis < 3; ++axis) {
      const double value = points[i][axis];
      if (!std::isfinite(value)) {
        throw InputError(name + ": " + what + " " + std::to_string(i) + " has a NaN or infinite coordinate");
      }
      if (std::abs(value) > max_coordinate) {
        throw InputError(name + ": " + what + " " + std::to_string(i) + " has a coordinate beyond 1e15 (" +
                         detail::format_number(value) + ")");
      }
    }
  }
}

void check_model(const std::string& name, const Model& model) {
  const TriangleMesh& mesh = model.mesh;
  if (mesh.positions.size() > std::numeric_limits<std::uint32_t>::max()) {
    throw InputError(name + ": too many vertices (" + std::to_string(mesh.positions.size()) + ")");
  }
  if (mesh.triangles.empty() && model.cloud.positions.empty()) {
    if (mesh.positions.empty()) throw InputError(name + ": empty model (no triangles or points)");
    throw InputError(name + ": empty model (" + std::to_string(mesh.positions.size()) + " vertices but no faces)");
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (std::uint32_t index : mesh.triangles[t]) {
      if (index >= mesh.positions.size()) {
        throw InputError(name + ": triangle " + std::to_string(t) + " uses vertex " + std::to_string(index) +
                         " but there are only " + std::to_string(mesh.positions.size()));
      }
    }
  }
  if (!mesh.materials.empty() && mesh.materials.size() != mesh.triangles.size())
    throw std::logic_error(name + ": the reader gave " + std::to_string(mesh.materials.size()) + " materials for " +
                           std::to_string(mesh.triangles.size()) + " triangles");
  for (std::uint32_t material : mesh.materials)
    if (material >= model.materials.size()) throw std::logic_error(name + ": material index out of range");
  check_coordinates(name, mesh.positions, "vertex");
  check_coordinates(name, model.cloud.positions, "point");
}

}  // namespace

Model read_model(const std::filesystem::path& path) {
  const std::string name = path.string();
  const std::string extension = lower_extension(path);
  const bool known = extension == ".obj" || extension == ".off" || extension == ".ply" || extension == ".stl" ||
                     extension == ".gltf" || extension == ".glb" || extension == ".xyz";
  if (!known) {
    throw InputError(name + ": unknown model format '" + extension +
                     "' (supported: .obj .off .ply .stl .gltf .glb .xyz)");
  }
  const std::string bytes = load_file(path);
  Model model;
  if (extension == ".obj") {
    model = detail::read_obj(path, bytes);
  } else if (extension == ".off") {
    model = detail::read_off(name, bytes);
  } else if (extension == ".ply") {
    model = detail::read_ply(name, bytes);
  } else if (extension == ".stl") {
    model = detail::read_stl(name, bytes);
  } else if (extension == ".xyz") {
    model = detail::read_xyz(name, bytes);
  } else {
    model = detail::read_gltf(path, bytes, extension == ".glb");
  }
  check_model(name, model);
  model.source_path = name;
  return model;
}

namespace {

/// The writable extension of `path` (lower case); InputError for a format that cannot be written.
std::string output_extension(const std::filesystem::path& path) {
  const std::string extension = lower_extension(path);
  if (extension != ".obj" && extension != ".ply" && extension != ".glb") {
    throw InputError(path.string() + ": cannot write format '" + extension + "' (supported: .obj .ply .glb)");
  }
  return extension;
}

/// std::invalid_argument unless every triangle index names a vertex of `mesh`.
void check_triangle_indices(const TriangleMesh& mesh) {
  for (const Triangle& t : mesh.triangles) {
    for (std::uint32_t index : t) {
      if (index >= mesh.positions.size()) throw std::invalid_argument("write_mesh: triangle index out of range");
    }
  }
}

/// The diffuse colour of `material` as 0..255 channels.
Rgb diffuse_rgb(const Material& material) {
  Rgb rgb{};
  for (int c = 0; c < 3; ++c)
    rgb[static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(material.diffuse[c], 0.0, 1.0)));
  return rgb;
}

}  // namespace

void write_mesh(const std::filesystem::path& path, const TriangleMesh& mesh, const std::vector<Rgb>* vertex_colors) {
  const std::string extension = output_extension(path);
  if (vertex_colors && vertex_colors->size() != mesh.positions.size()) {
    throw std::invalid_argument("write_mesh: " + std::to_string(vertex_colors->size()) + " colours for " +
                                std::to_string(mesh.positions.size()) + " vertices");
  }
  check_triangle_indices(mesh);
  write_file_atomically(path, [&](std::ostream& out) {
    if (extension == ".obj") {
      detail::write_obj(out, mesh);
    } else if (extension == ".ply") {
      detail::write_ply(out, mesh, vertex_colors);
    } else {
      detail::write_glb(out, mesh, vertex_colors);
    }
  });
}

void write_point_cloud(const std::filesystem::path& path, const PointCloud& cloud, const std::vector<Rgb>* colors) {
  if (output_extension(path) != ".ply") throw InputError(path.string() + ": point clouds are written as .ply only");
  if (colors && colors->size() != cloud.positions.size())
    throw std::invalid_argument("write_point_cloud: " + std::to_string(colors->size()) + " colours for " +
                                std::to_string(cloud.positions.size()) + " points");
  write_file_atomically(path, [&](std::ostream& out) { detail::write_ply_points(out, cloud, colors); });
}

void write_mesh_with_materials(const std::filesystem::path& path, const TriangleMesh& mesh,
                               const std::vector<Material>& materials) {
  if (materials.empty() || !mesh.has_materials()) {
    write_mesh(path, mesh);
    return;
  }
  const std::string extension = output_extension(path);
  check_triangle_indices(mesh);
  for (std::uint32_t m : mesh.materials) {
    if (m >= materials.size()) throw std::invalid_argument("write_mesh_with_materials: material index out of range");
  }
  if (extension == ".obj") {
    std::filesystem::path library = path;
    library.replace_extension(".mtl");
    const detail::ObjMaterials names{library.filename().string(), detail::obj_material_names(materials)};
    // The library first: the OBJ never names a file that is not there.
    write_file_atomically(library, [&](std::ostream& out) { detail::write_mtl(out, materials, names.names); });
    write_file_atomically(path, [&](std::ostream& out) { detail::write_obj(out, mesh, &names); });
  } else if (extension == ".ply") {
    std::vector<Rgb> face_colors;
    face_colors.reserve(mesh.triangles.size());
    for (std::uint32_t m : mesh.materials) face_colors.push_back(diffuse_rgb(materials[m]));
    write_file_atomically(path, [&](std::ostream& out) { detail::write_ply(out, mesh, nullptr, &face_colors); });
  } else {
    write_file_atomically(path, [&](std::ostream& out) { detail::write_glb(out, mesh, nullptr, &materials); });
  }
}

}  // namespace dg
