#include "geometry/slab_cut.h"

#include "geometry/submesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace dg {
namespace {

// Splits every triangle along one plane n . x = offset; `origin` (one entry per triangle of
// `mesh`) is replaced by one entry per triangle of the result, each piece keeping its triangle's
// (and its material).
TriangleMesh cut_along_plane(const TriangleMesh& mesh, const Vec3& normal, double offset, double tolerance,
                             std::vector<std::uint32_t>& origin) {
  TriangleMesh out;
  std::vector<std::uint32_t> out_origin;
  const bool has_materials = mesh.has_materials();
  out.positions = mesh.positions;
  std::vector<double> side(out.positions.size());
  for (std::size_t v = 0; v < out.positions.size(); ++v) {
    double d = normal.dot(out.positions[v]) - offset;
    if (std::abs(d) <= tolerance && d != 0.0) {
      out.positions[v] -= d * normal;  // snap onto the plane
      d = 0.0;
    }
    side[v] = d;
  }
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> crossings;
  auto crossing = [&](std::uint32_t a, std::uint32_t b) {
    const auto key = std::minmax(a, b);
    const auto found = crossings.find(key);
    if (found != crossings.end()) return found->second;
    const std::uint32_t lo = key.first, hi = key.second;  // same arithmetic from both triangles
    const double t = side[lo] / (side[lo] - side[hi]);
    const Vec3 p = out.positions[lo] + t * (out.positions[hi] - out.positions[lo]);
    const auto index = static_cast<std::uint32_t>(out.positions.size());
    out.positions.push_back(p - (normal.dot(p) - offset) * normal);
    side.push_back(0.0);
    crossings.emplace(key, index);
    return index;
  };
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    // Rotate so that the corner alone on its side (if any) comes first.
    int alone = -1;
    for (int k = 0; k < 3; ++k) {
      const double a = side[tri[k]], b = side[tri[(k + 1) % 3]], c = side[tri[(k + 2) % 3]];
      if ((a > 0.0 && b < 0.0 && c < 0.0) || (a < 0.0 && b > 0.0 && c > 0.0) || (a > 0.0 && b < 0.0 && c == 0.0) ||
          (a < 0.0 && b > 0.0 && c == 0.0) || (a > 0.0 && b == 0.0 && c < 0.0) || (a < 0.0 && b == 0.0 && c > 0.0)) {
        alone = k;
        break;
      }
    }
    if (alone < 0) {
      out.triangles.push_back(tri);
      out_origin.push_back(origin[t]);
      if (has_materials) out.materials.push_back(mesh.materials[t]);
      continue;
    }
    const std::uint32_t a = tri[alone], b = tri[(alone + 1) % 3], c = tri[(alone + 2) % 3];
    if (side[c] == 0.0) {  // plane through c: two triangles
      const std::uint32_t ab = crossing(a, b);
      out.triangles.push_back({a, ab, c});
      out.triangles.push_back({ab, b, c});
    } else if (side[b] == 0.0) {  // plane through b
      const std::uint32_t ca = crossing(c, a);
      out.triangles.push_back({a, b, ca});
      out.triangles.push_back({ca, b, c});
    } else {  // a alone: one triangle on its side, two on the other
      const std::uint32_t ab = crossing(a, b), ca = crossing(c, a);
      out.triangles.push_back({a, ab, ca});
      // The quad ab, b, c, ca is split by the diagonal from the higher-indexed of b and c, so a
      // back-to-back duplicate (the same corners in the other order) is split the same way and
      // stays an exact duplicate.
      if (c > b) {
        out.triangles.push_back({ab, b, c});
        out.triangles.push_back({ab, c, ca});
      } else {
        out.triangles.push_back({ab, b, ca});
        out.triangles.push_back({b, c, ca});
      }
    }
    out_origin.resize(out.triangles.size(), origin[t]);
    if (has_materials) out.materials.resize(out.triangles.size(), mesh.materials[t]);
  }
  origin = std::move(out_origin);
  return out;
}

}  // namespace

TriangleMesh cut_along_planes(const TriangleMesh& mesh, const Vec3& direction, const std::vector<double>& cuts,
                              double tolerance, std::vector<std::uint32_t>* origin) {
  std::vector<std::uint32_t> own;
  if (!origin) {
    own.resize(mesh.triangles.size());
    std::iota(own.begin(), own.end(), 0u);
    origin = &own;
  }
  TriangleMesh result = mesh;
  for (double offset : cuts) result = cut_along_plane(result, direction, offset, tolerance, *origin);
  return result;
}

std::size_t slab_of(const TriangleMesh& mesh, std::size_t t, const Vec3& direction, const std::vector<double>& cuts) {
  const auto [a, b, c] = mesh.corners(t);
  const double s = direction.dot((a + b + c) / 3.0);
  return static_cast<std::size_t>(std::upper_bound(cuts.begin(), cuts.end(), s) - cuts.begin());
}

double triangle_area_below(double s0, double s1, double s2, double area, double s) {
  // Quadratic in s on each side of s1.
  if (s <= s0) return 0.0;
  if (s >= s2) return area;
  if (s <= s1) return area * (s - s0) * (s - s0) / ((s1 - s0) * (s2 - s0));
  return area * (1.0 - (s2 - s) * (s2 - s) / ((s2 - s0) * (s2 - s1)));
}

namespace {

// Positions of a triangle's corners along `direction`, ascending.
std::array<double, 3> sorted_positions(const TriangleMesh& mesh, std::size_t t, const Vec3& direction) {
  const auto [a, b, c] = mesh.corners(t);
  std::array<double, 3> s{direction.dot(a), direction.dot(b), direction.dot(c)};
  std::sort(s.begin(), s.end());
  return s;
}

// The triangles `reaching` of `mesh` cut along the planes at lo and hi, those between them kept.
TriangleMesh cut_out_slab(const TriangleMesh& mesh, const std::vector<std::size_t>& reaching, const Vec3& direction,
                          double lo, double hi, double tolerance) {
  const std::vector<double> cuts{lo, hi};
  const TriangleMesh cut = cut_along_planes(submesh(mesh, reaching), direction, cuts, tolerance);
  std::vector<std::size_t> inside;
  for (std::size_t t = 0; t < cut.triangles.size(); ++t)
    if (slab_of(cut, t, direction, cuts) == 1) inside.push_back(t);
  return submesh(cut, inside);
}

}  // namespace

SlabTable::SlabTable(const TriangleMesh& mesh, const Vec3& direction, double start, double pitch)
    : mesh_(mesh), direction_(direction), start_(start), pitch_(pitch) {
  if (mesh.triangles.empty()) return;
  // Slab k holds a triangle when s2 > start + k pitch and s0 < start + (k + 1) pitch; its area
  // there is what lies below the upper plane minus what lies below the lower one.
  auto lower = [&](int k) { return start + k * pitch; };
  auto upper = [&](int k) { return start + (k + 1) * pitch; };
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  for (const Vec3& p : mesh.positions) {
    lowest = std::min(lowest, direction.dot(p));
    highest = std::max(highest, direction.dot(p));
  }
  first_ = static_cast<int>(std::floor((lowest - start) / pitch)) - 1;
  const int last = static_cast<int>(std::floor((highest - start) / pitch)) + 1;
  triangles_.resize(static_cast<std::size_t>(last - first_ + 1));
  areas_.assign(triangles_.size(), 0.0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::array<double, 3> s = sorted_positions(mesh, t, direction);
    const double whole = 0.5 * mesh.area_vector(t).norm();
    const int from = std::max(first_, static_cast<int>(std::floor((s[0] - start) / pitch)) - 1);
    const int to = std::min(last, static_cast<int>(std::floor((s[2] - start) / pitch)) + 1);
    for (int k = from; k <= to; ++k) {
      const double lo = lower(k), hi = upper(k);
      if (s[2] <= lo || s[0] >= hi) continue;
      const auto i = static_cast<std::size_t>(k - first_);
      triangles_[i].push_back(t);
      areas_[i] += triangle_area_below(s[0], s[1], s[2], whole, hi) - triangle_area_below(s[0], s[1], s[2], whole, lo);
    }
  }
}

double SlabTable::area(int k) const {
  if (k < first_ || k - first_ >= static_cast<int>(areas_.size())) return 0.0;
  return areas_[static_cast<std::size_t>(k - first_)];
}

TriangleMesh SlabTable::mesh(int k, double tolerance) const {
  static const std::vector<std::size_t> none;
  const bool inside = k >= first_ && k - first_ < static_cast<int>(triangles_.size());
  return cut_out_slab(mesh_, inside ? triangles_[static_cast<std::size_t>(k - first_)] : none, direction_,
                      start_ + k * pitch_, start_ + (k + 1) * pitch_, tolerance);
}

void drop_repeated_corners(TriangleMesh& mesh) {
  const bool has_materials = mesh.has_materials();
  std::size_t count = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle tri = mesh.triangles[t];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) continue;
    if (has_materials) mesh.materials[count] = mesh.materials[t];
    mesh.triangles[count++] = tri;
  }
  mesh.triangles.resize(count);
  if (has_materials) mesh.materials.resize(count);
}

}  // namespace dg
