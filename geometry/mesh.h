#pragma once
// Triangle meshes and point clouds: the input every 3D stage works on.

#include "geometry/types.h"

#include <string>
#include <vector>

namespace dg {

/// Indexed triangle mesh in model units. Triangles are counter-clockwise seen from the front.
struct TriangleMesh {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;

  /// Bounding box of all positions (also of unreferenced ones).
  BoundingBox bounds() const;
  /// Corner positions of triangle t.
  std::array<Vec3, 3> corners(std::size_t t) const;
  /// Unnormalized normal (cross product of the edges; length = 2 * area).
  Vec3 area_vector(std::size_t t) const;
  /// Total surface area in square model units.
  double area() const;
};

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

  /// True when the model is a point cloud (no triangles, points only).
  bool is_point_cloud() const { return mesh.triangles.empty() && !cloud.positions.empty(); }
  /// Bounding box of whatever the model holds.
  BoundingBox bounds() const { return is_point_cloud() ? cloud.bounds() : mesh.bounds(); }
};

}  // namespace dg
