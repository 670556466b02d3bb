#include "support/mesh_distance.h"

#include <algorithm>
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

double one_sided_distance(const TriangleMesh& from, const TriangleMesh& to) {
  std::vector<Vec3> samples = from.positions;
  for (std::size_t t = 0; t < from.triangles.size(); ++t) {
    const auto [a, b, c] = from.corners(t);
    samples.push_back((a + b + c) / 3.0);
  }
  double worst = 0.0;
  for (const Vec3& p : samples) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t t = 0; t < to.triangles.size() && best > 0.0; ++t) {
      const auto [a, b, c] = to.corners(t);
      best = std::min(best, point_triangle_distance(p, a, b, c));
    }
    worst = std::max(worst, best);
  }
  return worst;
}

double hausdorff_distance(const TriangleMesh& a, const TriangleMesh& b) {
  return std::max(one_sided_distance(a, b), one_sided_distance(b, a));
}

}  // namespace dg::test
