// gear(teeth): a spur gear lying in the xy plane, extruded along +z from 0 to `thickness`,
// with `teeth` identical teeth and a polygonal hole, as one closed surface.
//
// Tooth k occupies the angle sector [k, k+1) * 360/teeth degrees about +z; its outline is the
// tooth profile below rotated by that angle. count = teeth; the repetition is the rotation by
// 360/teeth degrees about the z axis through the origin.
//
// Profile (angles as fractions of the tooth sector, radii from the module m): root radius
// R - 1.25 m at 0 and 0.15, straight flank to the tip radius R + m at 0.35, tip at 0.5, 0.65,
// straight flank back to the root at 0.85 (R = m * teeth / 2, the pitch radius). The hole is a
// polygon of radius hole_ratio * R with one vertex at the angle of each outline vertex.
// detail k splits every outline and hole segment into k, the ring between them into k rings and
// the thickness into k layers (the shape stays the same).

#include "assets/generator/ground_truth.h"
#include "assets/generator/mesh_builder.h"
#include "assets/generator/models.h"
#include "assets/generator/subdivision.h"
#include "geometry/errors.h"

#include <array>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace dg::assets {

namespace {

/// Tooth profile vertex: on the tip circle (else the root circle), at `fraction` of the sector.
struct ProfilePoint {
  bool tip;
  double fraction;
};
constexpr std::array<ProfilePoint, 6> kProfile = {
    {{false, 0.0}, {false, 0.15}, {true, 0.35}, {true, 0.5}, {true, 0.65}, {false, 0.85}}};

/// Rotates p by angle radians about the origin.
Vec2 rotated(const Vec2& p, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y());
}

}  // namespace

Asset make_gear(const nlohmann::json& params) {
  Parameters p = read_parameters("gear", params);
  const int teeth = integer_parameter(p, "teeth", 12, 6, 10000);
  const double module = number_parameter(p, "module", 0.02, 0.0001, 10.0);
  const double thickness = number_parameter(p, "thickness", 0.03, 0.0001, 100.0);
  const double hole_ratio = number_parameter(p, "hole_ratio", 0.4, 0.05, 0.5);
  const int detail = integer_parameter(p, "detail", 1, 1, 1000);
  reject_unknown_parameters(p);

  const double pitch_radius = module * teeth / 2;
  const double root = pitch_radius - 1.25 * module, tip = pitch_radius + module;
  const double hole = hole_ratio * pitch_radius;
  if (hole >= 0.9 * root) throw InputError(fmt::format("gear: hole_ratio {} leaves no material at the root", hole_ratio));
  const double sector = 2 * std::numbers::pi / teeth;

  // Base outline and hole polygons: tooth k's points are tooth 0's points rotated by k * sector.
  std::vector<Vec2> outline, inner;
  for (int k = 0; k < teeth; ++k) {
    for (const ProfilePoint& q : kProfile) {
      const double angle = q.fraction * sector;
      outline.push_back(rotated(Vec2((q.tip ? tip : root) * std::cos(angle), (q.tip ? tip : root) * std::sin(angle)), k * sector));
      inner.push_back(rotated(Vec2(hole * std::cos(angle), hole * std::sin(angle)), k * sector));
    }
  }

  MeshBuilder builder;
  const std::size_t count = outline.size();
  const int d = detail;
  for (std::size_t v = 0; v < count; ++v) {
    const std::size_t w = (v + 1) % count;
    for (int i = 0; i < d; ++i) {
      const Vec2 o0 = split_point(outline[v], outline[w], i, d), o1 = split_point(outline[v], outline[w], i + 1, d);
      const Vec2 h0 = split_point(inner[v], inner[w], i, d), h1 = split_point(inner[v], inner[w], i + 1, d);
      // Top (+z) and bottom (-z) faces: rings from the hole (q = 0) to the outline (q = d).
      for (int q = 0; q < d; ++q) {
        const Vec2 a = split_point(h0, o0, q, d), b = split_point(h0, o0, q + 1, d);
        const Vec2 c = split_point(h1, o1, q + 1, d), e = split_point(h1, o1, q, d);
        builder.quad(at_height(a, thickness), at_height(b, thickness), at_height(c, thickness), at_height(e, thickness));
        builder.quad(at_height(a, 0.0), at_height(e, 0.0), at_height(c, 0.0), at_height(b, 0.0));
      }
      // Outline side (normal away from the axis) and hole side (normal towards the axis).
      for (int l = 0; l < d; ++l) {
        const double z0 = split_value(0.0, thickness, l, d), z1 = split_value(0.0, thickness, l + 1, d);
        builder.quad(at_height(o0, z0), at_height(o1, z0), at_height(o1, z1), at_height(o0, z1));
        builder.quad(at_height(h1, z0), at_height(h0, z0), at_height(h0, z1), at_height(h1, z1));
      }
    }
  }
  TriangleMesh mesh = builder.take();

  Repetition rep = rotation_repetition(
      "teeth", 360.0 / teeth, teeth,
      "tooth k: the gear's sector of angles [k, k+1) * 360/teeth degrees about +z (outline, faces and hole wall); "
      "count = teeth");
  // Sector boundaries are shifted by 1e-9 rad so that vertices on a boundary ray belong to one tooth.
  rep.measure = measure_unit(mesh, [sector](const Vec3& x) {
    const double angle = std::atan2(x.y(), x.x());
    return angle >= -1e-9 && angle < sector - 1e-9;
  });
  const nlohmann::json notes = {
      {"description", "spur gear in the xy plane, extruded along +z, with a polygonal hole"},
      {"dimensions",
       {{"pitch_radius", pitch_radius}, {"root_radius", root}, {"tip_radius", tip}, {"hole_radius", hole}}}};
  return finish_asset(fmt::format("gear_{}", teeth), p, std::move(mesh), {rep}, nullptr, notes);
}

}  // namespace dg::assets
