#include "grammar/sliding_units.h"

#include "geometry/slab_cut.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace dg {
namespace {

// Sine of the angle within which the velocity counts as tangent (1 degree, the cells' angle
// tolerance).
const double kTangent = std::sin(std::numbers::pi / 180.0);

// Share of the unit's area that may face along the motion (slivers, rounding).
constexpr double kFacingShare = 1e-3;

}  // namespace

bool unit_only_slides(const TriangleMesh& mesh, const GridDirection& direction) {
  const Vec3& d = direction.direction;
  const double lo = direction.cut + direction.head_units * direction.pitch, hi = lo + direction.pitch;
  const ScrewParameters screw = screw_parameters(direction.motion);
  const bool translation = screw.angle < 1e-12;
  // Velocity fields tested: 0 the motion's, 1 (screws only) its slide alone (a faceted column
  // turned by the screw onto itself is an extrusion along the axis, yet its facets face the turn).
  const std::size_t field_count = translation ? 1 : 2;
  auto velocity = [&](std::size_t field, const Vec3& x) -> Vec3 {
    if (translation) return direction.motion.translation;
    if (field == 1) return screw.axis;
    return screw.angle * screw.axis.cross(x - screw.axis_point) + screw.slide * screw.axis;
  };
  // Not parallel to the velocity at either end (its direction, unit).
  auto crosses_flow = [&](std::size_t field, const Vec3& a, const Vec3& b) {
    const Vec3 along = (b - a).normalized();
    const std::array<Vec3, 2> ends{a, b};
    return std::any_of(ends.begin(), ends.end(), [&](const Vec3& x) {
      const Vec3 v = velocity(field, x);
      return v.norm() > 0.0 && along.cross(v.normalized()).norm() > kTangent;
    });
  };
  double area = 0.0;
  std::array<double, 2> facing{0.0, 0.0};
  // Per edge: its triangles, and whether they have more than one material.
  struct EdgeUse {
    int triangles = 0;
    std::uint32_t material = 0;
    bool mixed = false;
  };
  std::map<std::pair<std::uint32_t, std::uint32_t>, EdgeUse> edge_uses;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    std::array<double, 3> s{d.dot(a), d.dot(b), d.dot(c)};
    std::sort(s.begin(), s.end());
    if (s[2] <= lo || s[0] >= hi) continue;
    const Vec3 normal_area = mesh.area_vector(t);
    const double whole = 0.5 * normal_area.norm();
    const double inside = triangle_area_below(s[0], s[1], s[2], whole, hi) - triangle_area_below(s[0], s[1], s[2], whole, lo);
    area += inside;
    if (whole > 0.0) {
      const Vec3 normal = normal_area.normalized();
      const std::array<Vec3, 3> corners{a, b, c};
      for (std::size_t f = 0; f < field_count; ++f) {
        const bool faces = std::any_of(corners.begin(), corners.end(), [&](const Vec3& x) {
          const Vec3 v = velocity(f, x);
          return v.norm() > 0.0 && std::abs(normal.dot(v.normalized())) > kTangent;
        });
        if (faces) facing[f] += inside;
      }
    }
    const Triangle& tri = mesh.triangles[t];
    const std::uint32_t material = mesh.has_materials() ? mesh.materials[t] : 0;
    for (int k = 0; k < 3; ++k) {
      EdgeUse& use = edge_uses[std::minmax(tri[k], tri[(k + 1) % 3])];
      use.mixed = use.mixed || (use.triangles > 0 && use.material != material);
      use.material = material;
      ++use.triangles;
    }
  }
  if (!(area > 0.0)) return false;
  // An open edge across the flow ends the surface inside the unit (a card-like baluster); a
  // border between materials across it ends a painted element (a window on a flat wall).
  auto slides_along = [&](std::size_t field) {
    if (facing[field] > kFacingShare * area) return false;
    for (const auto& [edge, use] : edge_uses) {
      if (use.triangles != 1 && !use.mixed) continue;
      const Vec3 &a = mesh.positions[edge.first], &b = mesh.positions[edge.second];
      const double sa = d.dot(a), sb = d.dot(b);
      if (std::max(sa, sb) > lo && std::min(sa, sb) < hi && crosses_flow(field, a, b)) return false;
    }
    return true;
  };
  return slides_along(0) || (field_count > 1 && slides_along(1));
}

}  // namespace dg
