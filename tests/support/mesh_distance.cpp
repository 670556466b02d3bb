#include "support/mesh_distance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace dg::test {

double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // Closest point by regions (Voronoi regions of vertices, edges and the face).
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return (p - a).norm();
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return (p - b).norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return (p - c).norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  const double denominator = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denominator) + ac * (vc * denominator))).norm();
}

namespace {

// The triangles of a mesh bucketed in a uniform grid (by the cells their bounding boxes touch)
// over a box that holds every query point, for exact nearest-triangle distances.
class TriangleGrid {
 public:
  TriangleGrid(const TriangleMesh& mesh, const BoundingBox& queries) : mesh_(mesh) {
    BoundingBox box = queries;
    for (const Vec3& p : mesh.positions) box.add(p);
    origin_ = box.min;
    const Vec3 extent = (box.max - box.min).cwiseMax(Vec3::Constant(1e-12));
    // About two cells per triangle, at most 128 along an axis.
    const double volume = extent.x() * extent.y() * extent.z();
    cell_ = std::cbrt(volume / (2.0 * static_cast<double>(std::max<std::size_t>(mesh.triangles.size(), 1))));
    cell_ = std::max(cell_, extent.maxCoeff() / 128.0);
    for (int axis = 0; axis < 3; ++axis) size_[axis] = std::max(1, static_cast<int>(std::ceil(extent[axis] / cell_)));
    buckets_.resize(static_cast<std::size_t>(size_[0]) * size_[1] * size_[2]);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const auto [a, b, c] = mesh.corners(t);
      const std::array<int, 3> lo = cell_of(a.cwiseMin(b).cwiseMin(c)), hi = cell_of(a.cwiseMax(b).cwiseMax(c));
      for (int x = lo[0]; x <= hi[0]; ++x)
        for (int y = lo[1]; y <= hi[1]; ++y)
          for (int z = lo[2]; z <= hi[2]; ++z) buckets_[index(x, y, z)].push_back(static_cast<std::uint32_t>(t));
    }
  }

  /// Distance from p (inside the query box) to the nearest triangle: rings of cells around p's
  /// cell, until the next ring cannot hold anything nearer.
  double distance(const Vec3& p) const {
    const std::array<int, 3> centre = cell_of(p);
    double best = std::numeric_limits<double>::infinity();
    const int rings = std::max({size_[0], size_[1], size_[2]});
    for (int k = 0; k <= rings; ++k) {
      for (int x = centre[0] - k; x <= centre[0] + k; ++x)
        for (int y = centre[1] - k; y <= centre[1] + k; ++y)
          for (int z = centre[2] - k; z <= centre[2] + k; ++z) {
            const bool on_ring = std::abs(x - centre[0]) == k || std::abs(y - centre[1]) == k || std::abs(z - centre[2]) == k;
            if (!on_ring || x < 0 || y < 0 || z < 0 || x >= size_[0] || y >= size_[1] || z >= size_[2]) continue;
            for (std::uint32_t t : buckets_[index(x, y, z)]) {
              const auto [a, b, c] = mesh_.corners(t);
              best = std::min(best, point_triangle_distance(p, a, b, c));
            }
          }
      if (best <= static_cast<double>(k) * cell_) break;  // every later ring is at least k cells away
    }
    return best;
  }

 private:
  std::array<int, 3> cell_of(const Vec3& p) const {
    std::array<int, 3> c{};
    for (int axis = 0; axis < 3; ++axis)
      c[axis] = std::clamp(static_cast<int>(std::floor((p[axis] - origin_[axis]) / cell_)), 0, size_[axis] - 1);
    return c;
  }
  std::size_t index(int x, int y, int z) const {
    return (static_cast<std::size_t>(x) * static_cast<std::size_t>(size_[1]) + static_cast<std::size_t>(y)) *
               static_cast<std::size_t>(size_[2]) + static_cast<std::size_t>(z);
  }

  const TriangleMesh& mesh_;
  Vec3 origin_;
  double cell_ = 1.0;
  std::array<int, 3> size_{1, 1, 1};
  std::vector<std::vector<std::uint32_t>> buckets_;
};

}  // namespace

double one_sided_distance(const TriangleMesh& from, const TriangleMesh& to) {
  std::vector<Vec3> samples = from.positions;
  for (std::size_t t = 0; t < from.triangles.size(); ++t) {
    const auto [a, b, c] = from.corners(t);
    samples.push_back((a + b + c) / 3.0);
  }
  if (samples.empty()) return 0.0;
  if (to.triangles.empty()) return std::numeric_limits<double>::infinity();
  BoundingBox box;
  for (const Vec3& p : samples) box.add(p);
  const TriangleGrid grid(to, box);
  double worst = 0.0;
  for (const Vec3& p : samples) worst = std::max(worst, grid.distance(p));
  return worst;
}

double hausdorff_distance(const TriangleMesh& a, const TriangleMesh& b) {
  return std::max(one_sided_distance(a, b), one_sided_distance(b, a));
}

}  // namespace dg::test
