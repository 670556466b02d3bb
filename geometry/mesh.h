#pragma once
// Triangle meshes and point clouds: the input every 3D stage works on.

#include "geometry/types.h"

#include <string>
#include <vector>

namespace dg {

/// A surface material as the model file names it (OBJ `usemtl` / MTL `newmtl`, glTF material),
/// with the colour it shows: MTL `Kd` or glTF `baseColorFactor`, linear RGB in 0..1, and its
/// opacity in 0..1 (1 = opaque): MTL `d` (or 1 - `Tr`), glTF alpha of a BLEND material.
struct Material {
  std::string name;
  Vec3 diffuse = Vec3::Constant(0.8);
  double opacity = 1.0;

  friend bool operator==(const Material&, const Material&) = default;
};

/// Indexed triangle mesh in model units. Triangles are counter-clockwise seen from the front.
struct TriangleMesh {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  /// Material of each triangle: an index into the material list that travels with the mesh
  /// (Model::materials, a grammar's materials), or empty when the model names no materials.
  /// Whatever builds triangles out of other triangles gives each piece its source's material.
  std::vector<std::uint32_t> materials;

  /// True when every triangle carries a material index.
  bool has_materials() const { return !materials.empty() && materials.size() == triangles.size(); }

  /// Bounding box of all positions (also of unreferenced ones).
  BoundingBox bounds() const;
  /// Corner positions of triangle t.
  std::array<Vec3, 3> corners(std::size_t t) const;
  /// Unnormalized normal (cross product of the edges; length = 2 * area).
  Vec3 area_vector(std::size_t t) const;
  /// Total surface area in square model units.
  double area() const;
};

/// One unit normal per vertex of `mesh`: the normalized sum of the unit normals of the triangles
/// that use it (zero for a vertex no triangle with area uses).
std::vector<Vec3> vertex_normals(const TriangleMesh& mesh);

/// Unordered points, optionally with unit normals (normals empty or one per point).
struct PointCloud {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;

  /// Bounding box of all points.
  BoundingBox bounds() const;
  /// True when every point carries a normal.
  bool has_normals() const { return !positions.empty() && normals.size() == positions.size(); }
};

/// What a model file held: a mesh, or a point cloud when the file had no faces.
struct Model {
  std::string source_path;  ///< file it was read from ("" when built in code)
  TriangleMesh mesh;
  PointCloud cloud;
  std::vector<Material> materials;  ///< indexed by mesh.materials; empty when the file named none

  /// True when the model is a point cloud (no triangles, points only).
  bool is_point_cloud() const { return mesh.triangles.empty() && !cloud.positions.empty(); }
  /// Bounding box of whatever the model holds.
  BoundingBox bounds() const { return is_point_cloud() ? cloud.bounds() : mesh.bounds(); }
};

}  // namespace dg
