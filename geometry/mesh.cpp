#include "geometry/mesh.h"

namespace dg {

BoundingBox TriangleMesh::bounds() const {
  BoundingBox box;
  for (const Vec3& p : positions) box.add(p);
  return box;
}

std::array<Vec3, 3> TriangleMesh::corners(std::size_t t) const {
  const Triangle& tri = triangles[t];
  return {positions[tri[0]], positions[tri[1]], positions[tri[2]]};
}

Vec3 TriangleMesh::area_vector(std::size_t t) const {
  const auto [a, b, c] = corners(t);
  return (b - a).cross(c - a);
}

double TriangleMesh::area() const {
  double sum = 0.0;
  for (std::size_t t = 0; t < triangles.size(); ++t) sum += 0.5 * area_vector(t).norm();
  return sum;
}

std::vector<Vec3> vertex_normals(const TriangleMesh& mesh) {
  std::vector<Vec3> normals(mesh.positions.size(), Vec3::Zero());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3 area_vector = mesh.area_vector(t);
    if (area_vector.squaredNorm() <= 0.0) continue;
    for (std::uint32_t v : mesh.triangles[t]) normals[v] += area_vector.normalized();
  }
  for (Vec3& n : normals)
    if (n.squaredNorm() > 0.0) n.normalize();
  return normals;
}

BoundingBox PointCloud::bounds() const {
  BoundingBox box;
  for (const Vec3& p : positions) box.add(p);
  return box;
}

}  // namespace dg
