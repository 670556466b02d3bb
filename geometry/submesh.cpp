#include "geometry/submesh.h"

#include <cstdint>
#include <numeric>

namespace dg {

TriangleMesh submesh(const TriangleMesh& mesh, const std::vector<std::size_t>& triangles) {
  std::vector<std::int64_t> remap(mesh.positions.size(), -1);
  TriangleMesh part;
  part.triangles.reserve(triangles.size());
  for (std::size_t t : triangles) {
    Triangle mapped;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = mesh.triangles[t][k];
      if (remap[v] < 0) {
        remap[v] = static_cast<std::int64_t>(part.positions.size());
        part.positions.push_back(mesh.positions[v]);
      }
      mapped[k] = static_cast<std::uint32_t>(remap[v]);
    }
    part.triangles.push_back(mapped);
    if (mesh.has_materials()) part.materials.push_back(mesh.materials[t]);
  }
  return part;
}

TriangleMesh without_unused_vertices(const TriangleMesh& mesh) {
  std::vector<std::size_t> all(mesh.triangles.size());
  std::iota(all.begin(), all.end(), std::size_t{0});
  return submesh(mesh, all);
}

TriangleMesh transformed(const TriangleMesh& mesh, const RigidTransform& motion) {
  TriangleMesh moved = mesh;
  for (Vec3& p : moved.positions) p = motion.apply(p);
  return moved;
}

void append_mesh(TriangleMesh& mesh, const TriangleMesh& part) {
  const bool keep_materials = (mesh.triangles.empty() || mesh.has_materials()) && (part.triangles.empty() || part.has_materials());
  const auto base = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), part.positions.begin(), part.positions.end());
  for (const Triangle& t : part.triangles) mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  if (keep_materials)
    mesh.materials.insert(mesh.materials.end(), part.materials.begin(), part.materials.end());
  else
    mesh.materials.clear();
}

PointCloud subcloud(const PointCloud& cloud, const std::vector<std::uint32_t>& points) {
  PointCloud part;
  part.positions.reserve(points.size());
  for (std::uint32_t p : points) part.positions.push_back(cloud.positions[p]);
  if (cloud.has_normals()) {
    part.normals.reserve(points.size());
    for (std::uint32_t p : points) part.normals.push_back(cloud.normals[p]);
  }
  return part;
}

PointCloud transformed(const PointCloud& cloud, const RigidTransform& motion) {
  PointCloud moved = cloud;
  for (Vec3& p : moved.positions) p = motion.apply(p);
  for (Vec3& n : moved.normals) n = motion.rotation * n;
  return moved;
}

void append_points(PointCloud& cloud, const PointCloud& part) {
  if (part.positions.empty()) return;
  const bool keep_normals = (cloud.positions.empty() || cloud.has_normals()) && part.has_normals();
  if (!keep_normals) cloud.normals.clear();
  cloud.positions.insert(cloud.positions.end(), part.positions.begin(), part.positions.end());
  if (keep_normals) cloud.normals.insert(cloud.normals.end(), part.normals.begin(), part.normals.end());
}

}  // namespace dg
