#pragma once
// Internal: one writer per output format, streaming a complete file into `out`.
// model_io.cpp checks the arguments and wraps these in write_file_atomically.

#include "geometry/mesh.h"
#include "geometry/model_io.h"

#include <bit>
#include <cstring>
#include <ostream>
#include <string>
#include <vector>

namespace dg::detail {

/// Where an OBJ file takes its materials from: the MTL file name for `mtllib` and the name
/// `usemtl` gives each material (indexed like the mesh's material indices).
struct ObjMaterials {
  std::string library;
  std::vector<std::string> names;
};

/// OBJ text: "v x y z" with shortest round-trip decimals, then "f a b c" (1-based). With
/// `materials` (the mesh must carry material indices): "mtllib" after the header line and
/// "usemtl NAME" before each run of triangles of one material.
void write_obj(std::ostream& out, const TriangleMesh& mesh, const ObjMaterials* materials = nullptr);
/// Names for `materials` that MTL and OBJ lines can hold: whitespace becomes '_', an empty name
/// becomes "material_I", and a name used before gets "_I" appended until it is new (I = the
/// material's index).
std::vector<std::string> obj_material_names(const std::vector<Material>& materials);
/// MTL text: "newmtl NAME", "Kd r g b" (the diffuse colour) and, below 1, "d OPACITY" per
/// material, in order.
void write_mtl(std::ostream& out, const std::vector<Material>& materials, const std::vector<std::string>& names);
/// PLY binary little endian: double x y z (+ uchar red green blue), uchar/uint vertex_indices
/// lists (+ uchar red green blue per face with `face_colors`, one per triangle).
void write_ply(std::ostream& out, const TriangleMesh& mesh, const std::vector<Rgb>* colors,
               const std::vector<Rgb>* face_colors = nullptr);
/// PLY binary little endian of a point cloud: double x y z (+ double nx ny nz when every point
/// has a normal, + uchar red green blue with `colors`), no face element.
void write_ply_points(std::ostream& out, const PointCloud& cloud, const std::vector<Rgb>* colors);
/// glTF 2.0 binary: one scene, one node, one mesh; float32 POSITION with min/max, optional
/// COLOR_0 (normalized unsigned bytes), uint32 indices. One primitive, or with `materials` (the
/// mesh must carry material indices) one primitive per material used, in material order, each
/// naming its material (baseColorFactor = the diffuse colour and the opacity, alphaMode BLEND
/// below 1; not metallic, fully rough).
void write_glb(std::ostream& out, const TriangleMesh& mesh, const std::vector<Rgb>* colors,
               const std::vector<Material>* materials = nullptr);

/// Appends the little-endian bytes of an integer or floating-point value to `bytes`.
template <typename T>
void append_le(std::string& bytes, T value) {
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) {
    for (std::size_t i = sizeof(T); i-- > 0;) bytes.push_back(static_cast<char>(raw[i]));
  } else {
    bytes.append(reinterpret_cast<const char*>(raw), sizeof(T));
  }
}

}  // namespace dg::detail
