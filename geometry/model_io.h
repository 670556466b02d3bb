#pragma once
// Reading models (meshes and point clouds) and writing meshes, chosen by file extension.

#include "geometry/mesh.h"

#include <filesystem>
#include <optional>
#include <vector>

namespace dg {

/// The extension of `path` in lower case, with its dot (".glb"); empty when it has none.
std::string lower_extension(const std::filesystem::path& path);

/// Reads OBJ, OFF, PLY (ascii/binary), STL (ascii/binary), glTF 2.0 (.gltf/.glb) and XYZ.
/// Polygons are triangulated inside their outlines (geometry/polygon_triangulation.h); glTF instances of the default scene get their node transforms.
/// A PLY without faces and an XYZ file give a point cloud. Positions are NOT welded here
/// (see clean_mesh). Throws InputError naming the file and the problem (unreadable, unknown
/// format, malformed, empty, NaN/inf coordinates).
Model read_model(const std::filesystem::path& path);

/// RGB colour per vertex, 0..255.
using Rgb = std::array<std::uint8_t, 3>;

/// Writes a mesh as OBJ, PLY (binary little endian) or glTF binary (.glb) chosen by the
/// extension, atomically. `vertex_colors`, when given, has one colour per position (PLY and GLB
/// store it; OBJ ignores it). Throws InputError for an unknown extension or unwritable path.
void write_mesh(const std::filesystem::path& path, const TriangleMesh& mesh,
                const std::vector<Rgb>* vertex_colors = nullptr);

/// Writes a point cloud as binary little-endian PLY (double x y z, double nx ny nz when every
/// point has a normal, uchar red green blue with `colors`: one per point), atomically; the file
/// has no face element, so read_model gives the cloud back. Throws InputError unless the path
/// ends in .ply or when it cannot be written.
void write_point_cloud(const std::filesystem::path& path, const PointCloud& cloud, const std::vector<Rgb>* colors = nullptr);

/// Writes a mesh with its materials (`materials`, indexed by mesh.materials) as write_mesh does,
/// atomically: OBJ with "mtllib NAME.mtl" and "usemtl" before each run of triangles of one
/// material, plus NAME.mtl next to it ("newmtl", "Kd" = the diffuse colour, "d" = the opacity
/// below 1); PLY with a colour per face (the diffuse colour as uchar red green blue); GLB with one
/// primitive per material used, each with its material (baseColorFactor = the diffuse colour and
/// the opacity; alphaMode BLEND below 1). Without materials (an
/// empty list or a mesh without indices) the file is exactly what write_mesh writes. Throws as
/// write_mesh, and std::invalid_argument for a material index beyond the list.
void write_mesh_with_materials(const std::filesystem::path& path, const TriangleMesh& mesh,
                               const std::vector<Material>& materials);

}  // namespace dg
