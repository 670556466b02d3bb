#include "support/shapes.h"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace dg::test {

TriangleMesh make_box(const Vec3& lo, const Vec3& hi) {
  TriangleMesh mesh;
  const BoundingBox box{lo, hi};
  for (int corner = 0; corner < 8; ++corner) mesh.positions.push_back(box.corner(corner));
  // Faces as quads (counter-clockwise seen from outside).
  const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[2], q[3]});
  }
  return mesh;
}

TriangleMesh make_sphere(const Vec3& centre, double radius, int rings, int segments) {
  TriangleMesh mesh;
  mesh.positions.push_back(centre + Vec3(0, 0, radius));
  for (int r = 1; r < rings; ++r) {
    const double theta = std::numbers::pi * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double phi = 2.0 * std::numbers::pi * s / segments;
      mesh.positions.push_back(centre + radius * Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                                                      std::cos(theta)));
    }
  }
  mesh.positions.push_back(centre - Vec3(0, 0, radius));
  const auto ring_vertex = [&](int r, int s) { return static_cast<std::uint32_t>(1 + (r - 1) * segments + (s % segments)); };
  const auto south = static_cast<std::uint32_t>(mesh.positions.size() - 1);
  for (int s = 0; s < segments; ++s) {
    mesh.triangles.push_back({0, ring_vertex(1, s), ring_vertex(1, s + 1)});
    for (int r = 1; r + 1 < rings; ++r) {
      mesh.triangles.push_back({ring_vertex(r, s), ring_vertex(r + 1, s), ring_vertex(r + 1, s + 1)});
      mesh.triangles.push_back({ring_vertex(r, s), ring_vertex(r + 1, s + 1), ring_vertex(r, s + 1)});
    }
    mesh.triangles.push_back({ring_vertex(rings - 1, s), south, ring_vertex(rings - 1, s + 1)});
  }
  return mesh;
}

TriangleMesh make_torus(const Vec3& centre, const Eigen::Matrix3d& frame, double radius, double tube_radius, int segments,
                        int tube_segments) {
  TriangleMesh mesh;
  for (int i = 0; i < segments; ++i) {
    const double u = 2.0 * std::numbers::pi * i / segments;
    for (int j = 0; j < tube_segments; ++j) {
      const double v = 2.0 * std::numbers::pi * j / tube_segments;
      const double ring = radius + tube_radius * std::cos(v);
      mesh.positions.push_back(centre + frame * Vec3(ring * std::cos(u), ring * std::sin(u), tube_radius * std::sin(v)));
    }
  }
  const auto vertex = [&](int i, int j) { return static_cast<std::uint32_t>((i % segments) * tube_segments + (j % tube_segments)); };
  for (int i = 0; i < segments; ++i)
    for (int j = 0; j < tube_segments; ++j) {
      mesh.triangles.push_back({vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)});
      mesh.triangles.push_back({vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
    }
  return mesh;
}

TriangleMesh make_chain(int links) {
  TriangleMesh mesh;
  const Eigen::Matrix3d turned = Eigen::AngleAxisd(0.5 * std::numbers::pi, Vec3::UnitX()).toRotationMatrix();
  for (int k = 0; k < links; ++k)
    append(mesh, make_torus(Vec3(1.5 * k, 0.0, 0.0), k % 2 == 0 ? Eigen::Matrix3d::Identity() : turned, 1.0, 0.15, 20, 8));
  return mesh;
}

void append(TriangleMesh& mesh, const TriangleMesh& part) {
  const auto shift = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), part.positions.begin(), part.positions.end());
  for (Triangle t : part.triangles) mesh.triangles.push_back({t[0] + shift, t[1] + shift, t[2] + shift});
}

TriangleMesh split_at_centroids(const TriangleMesh& mesh) {
  TriangleMesh split = mesh;
  split.triangles.clear();
  split.materials.clear();
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    const auto m = static_cast<std::uint32_t>(split.positions.size());
    split.positions.push_back((a + b + c) / 3.0);
    const Triangle& tri = mesh.triangles[t];
    split.triangles.insert(split.triangles.end(), {{tri[0], tri[1], m}, {tri[1], tri[2], m}, {tri[2], tri[0], m}});
    if (mesh.has_materials()) split.materials.insert(split.materials.end(), 3, mesh.materials[t]);
  }
  return split;
}

Eigen::Matrix3d general_rotation() {
  return (Eigen::AngleAxisd(0.54, Vec3::UnitZ()) * Eigen::AngleAxisd(0.40, Vec3::UnitY()) *
          Eigen::AngleAxisd(0.30, Vec3::UnitX()))
      .toRotationMatrix();
}

void turn_generally(TriangleMesh& mesh) {
  const Eigen::Matrix3d rotation = general_rotation();
  for (Vec3& p : mesh.positions) p = rotation * p;
}

TriangleMesh pilaster_facade(int columns, int storeys) {
  const double height = 3.0 * storeys;
  TriangleMesh mesh = make_box(Vec3(0, 0, 0), Vec3(1.5 * columns + 0.3, height, 0.3));
  for (int c = 0; c < columns; ++c)
    for (int s = 0; s < storeys; ++s)
      append(mesh, make_box(Vec3(0.5 + 1.5 * c, 1 + 3.0 * s, 0.3), Vec3(1.3 + 1.5 * c, 2.2 + 3.0 * s, 0.4)));
  for (int k = 0; k <= columns / 3; ++k) append(mesh, make_box(Vec3(4.5 * k, 0, 0.3), Vec3(4.5 * k + 0.3, height, 0.5)));
  return mesh;
}

}  // namespace dg::test
