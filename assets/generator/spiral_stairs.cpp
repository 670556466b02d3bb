// spiral_stairs(steps): wedge-shaped steps around a central column, fused to it into one closed
// surface. Step i (i = 0 .. steps-1) spans the angles [i, i+1] * 360/steps_per_turn degrees
// about +z (counter-clockwise going up), radii [column_radius, outer_radius], and heights
// [(i+1) rise - thickness, (i+1) rise]; thickness < rise, so steps touch only the column.
// The column is a prism (steps_per_turn * 4 sides) from z = 0 to steps * rise + newel.
//
// Step i+1 is step i moved by the screw motion "rotate by 360/steps_per_turn degrees about +z,
// then lift by rise"; count = steps. The column side is split around every step opening so
// that no vertex lies inside another face's edge.

#include "assets/generator/ground_truth.h"
#include "assets/generator/mesh_builder.h"
#include "assets/generator/models.h"
#include "assets/generator/subdivision.h"
#include "geometry/errors.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <vector>

namespace dg::assets {

namespace {

constexpr int kSidesPerStep = 4;  // column (and step edge) polygon sides per step angle

struct Stairs {
  int steps = 0;
  int per_turn = 0;
  double rise = 0.0;
  double thickness = 0.0;
  double column_radius = 0.0;
  double outer_radius = 0.0;
  double height = 0.0;  // column top
  int detail = 1;

  /// Fine polygon vertices around the axis (kSidesPerStep * per_turn * detail).
  int fine_edges() const { return kSidesPerStep * per_turn * detail; }
  /// First fine edge of step i (its last is first + kSidesPerStep * detail), not reduced.
  int first_edge(int i) const { return i * kSidesPerStep * detail; }
  double bottom(int i) const { return (i + 1) * rise - thickness; }
  double top(int i) const { return (i + 1) * rise; }
};

/// Fine polygon vertex e (any integer, taken modulo the count) at radius r and height z; the
/// base polygon has kSidesPerStep * per_turn vertices, fine vertices split its sides evenly.
Vec3 ring_point(const Stairs& s, int e, double r, double z) {
  const int fine = s.fine_edges(), sides = fine / s.detail;
  const int m = ((e % fine) + fine) % fine;
  const int side = m / s.detail, part = m % s.detail;
  const auto corner = [&](int c) {
    const double angle = 2 * std::numbers::pi * (c % sides) / sides;
    return Vec2(r * std::cos(angle), r * std::sin(angle));
  };
  return at_height(split_point(corner(side), corner(side + 1), part, s.detail), z);
}

/// Position of fine edge e inside step i's edge range, counted from its first edge modulo a turn
/// (0 .. span is inside, span = kSidesPerStep * detail).
int edge_offset(const Stairs& s, int i, int e) {
  const int fine = s.fine_edges();
  return (((e - s.first_edge(i)) % fine) + fine) % fine;
}

/// Steps whose fine edge range [first, first + span] contains fine edge e.
std::vector<int> steps_at_edge(const Stairs& s, int e) {
  std::vector<int> result;
  for (int i = 0; i < s.steps; ++i) {
    if (edge_offset(s, i, e) <= kSidesPerStep * s.detail) result.push_back(i);
  }
  return result;
}

/// Heights of the column vertices on the vertical line through fine edge e: its ends, the
/// bottom and top of every step touching it (all step layers where a step's side face ends on
/// it), and every other gap split into `detail` parts.
std::vector<double> edge_heights(const Stairs& s, int e) {
  std::vector<double> hard = {0.0, s.height};
  std::vector<std::pair<double, double>> inside;  // step intervals along this edge
  for (int i : steps_at_edge(s, e)) {
    inside.emplace_back(s.bottom(i), s.top(i));
    const int offset = edge_offset(s, i, e);
    if (offset == 0 || offset == kSidesPerStep * s.detail) {
      for (int l = 0; l <= s.detail; ++l) hard.push_back(split_value(s.bottom(i), s.top(i), l, s.detail));
    } else {
      hard.push_back(s.bottom(i));
      hard.push_back(s.top(i));
    }
  }
  std::sort(hard.begin(), hard.end());
  hard.erase(std::unique(hard.begin(), hard.end()), hard.end());
  std::vector<double> heights;
  for (std::size_t k = 0; k + 1 < hard.size(); ++k) {
    const double lo = hard[k], hi = hard[k + 1];
    const bool in_step = std::any_of(inside.begin(), inside.end(), [&](const auto& iv) { return lo >= iv.first && hi <= iv.second; });
    const int parts = in_step ? 1 : s.detail;
    for (int l = 0; l < parts; ++l) heights.push_back(split_value(lo, hi, l, parts));
  }
  heights.push_back(s.height);
  return heights;
}

/// Column side between fine edges e and e+1 (normal away from the axis), leaving out the step
/// openings; each remaining piece is a ladder of triangles between the two vertical lines.
void add_column_strip(MeshBuilder& builder, const Stairs& s, int e) {
  const std::vector<double> left = edge_heights(s, e), right = edge_heights(s, e + 1);
  std::vector<std::pair<double, double>> holes;
  for (int i : steps_at_edge(s, e)) {
    if (edge_offset(s, i, e) < kSidesPerStep * s.detail) holes.emplace_back(s.bottom(i), s.top(i));
  }
  std::sort(holes.begin(), holes.end());
  std::vector<std::pair<double, double>> pieces;
  double start = 0.0;
  for (const auto& [lo, hi] : holes) {
    pieces.emplace_back(start, lo);
    start = hi;
  }
  pieces.emplace_back(start, s.height);
  for (const auto& [lo, hi] : pieces) {
    std::vector<double> l, r;
    std::copy_if(left.begin(), left.end(), std::back_inserter(l), [&](double z) { return z >= lo && z <= hi; });
    std::copy_if(right.begin(), right.end(), std::back_inserter(r), [&](double z) { return z >= lo && z <= hi; });
    std::size_t a = 0, b = 0;
    while (a + 1 < l.size() || b + 1 < r.size()) {
      const bool advance_left = b + 1 == r.size() || (a + 1 < l.size() && l[a + 1] < r[b + 1]);
      const Vec3 la = ring_point(s, e, s.column_radius, l[a]), rb = ring_point(s, e + 1, s.column_radius, r[b]);
      if (advance_left) {
        builder.triangle(la, rb, ring_point(s, e, s.column_radius, l[a + 1]));
        ++a;
      } else {
        builder.triangle(la, rb, ring_point(s, e + 1, s.column_radius, r[b + 1]));
        ++b;
      }
    }
  }
}

/// Step i without its inner face (which is the opening in the column).
void add_step(MeshBuilder& builder, const Stairs& s, int i) {
  const int d = s.detail, e0 = s.first_edge(i), e1 = e0 + kSidesPerStep * d;
  const double z0 = s.bottom(i), z1 = s.top(i);
  const auto radius = [&](int q) { return split_value(s.column_radius, s.outer_radius, q, d); };
  const auto layer = [&](int l) { return split_value(z0, z1, l, d); };
  for (int e = e0; e < e1; ++e) {
    for (int q = 0; q < d; ++q) {
      builder.quad(ring_point(s, e, radius(q), z1), ring_point(s, e, radius(q + 1), z1),
                   ring_point(s, e + 1, radius(q + 1), z1), ring_point(s, e + 1, radius(q), z1));
      builder.quad(ring_point(s, e, radius(q), z0), ring_point(s, e + 1, radius(q), z0),
                   ring_point(s, e + 1, radius(q + 1), z0), ring_point(s, e, radius(q + 1), z0));
    }
    for (int l = 0; l < d; ++l) {
      builder.quad(ring_point(s, e, s.outer_radius, layer(l)), ring_point(s, e + 1, s.outer_radius, layer(l)),
                   ring_point(s, e + 1, s.outer_radius, layer(l + 1)), ring_point(s, e, s.outer_radius, layer(l + 1)));
    }
  }
  for (int q = 0; q < d; ++q) {
    for (int l = 0; l < d; ++l) {
      builder.quad(ring_point(s, e0, radius(q), layer(l)), ring_point(s, e0, radius(q + 1), layer(l)),
                   ring_point(s, e0, radius(q + 1), layer(l + 1)), ring_point(s, e0, radius(q), layer(l + 1)));
      builder.quad(ring_point(s, e1, radius(q), layer(l)), ring_point(s, e1, radius(q), layer(l + 1)),
                   ring_point(s, e1, radius(q + 1), layer(l + 1)), ring_point(s, e1, radius(q + 1), layer(l)));
    }
  }
}

}  // namespace

Asset make_spiral_stairs(const nlohmann::json& params) {
  Parameters p = read_parameters("spiral_stairs", params);
  Stairs s;
  s.steps = integer_parameter(p, "steps", 12, 1, 10000);
  s.per_turn = integer_parameter(p, "steps_per_turn", 12, 3, 360);
  s.rise = number_parameter(p, "rise", 0.18, 0.01, 10.0);
  s.thickness = number_parameter(p, "step_thickness", 0.05, 0.001, 10.0);
  s.column_radius = number_parameter(p, "column_radius", 0.12, 0.01, 10.0);
  s.outer_radius = number_parameter(p, "outer_radius", 1.0, 0.02, 100.0);
  const double newel = number_parameter(p, "newel", 1.0, 0.01, 100.0);
  s.detail = integer_parameter(p, "detail", 1, 1, 1000);
  reject_unknown_parameters(p);
  if (s.thickness >= s.rise) throw InputError("spiral_stairs: step_thickness must be smaller than rise");
  if (s.outer_radius <= s.column_radius) throw InputError("spiral_stairs: outer_radius must exceed column_radius");
  s.height = s.steps * s.rise + newel;

  MeshBuilder builder;
  const int fine = s.fine_edges();
  const Vec3 bottom_centre(0.0, 0.0, 0.0), top_centre(0.0, 0.0, s.height);
  for (int e = 0; e < fine; ++e) {
    builder.triangle(bottom_centre, ring_point(s, e + 1, s.column_radius, 0.0), ring_point(s, e, s.column_radius, 0.0));
    builder.triangle(top_centre, ring_point(s, e, s.column_radius, s.height), ring_point(s, e + 1, s.column_radius, s.height));
    add_column_strip(builder, s, e);
  }
  for (int i = 0; i < s.steps; ++i) add_step(builder, s, i);
  TriangleMesh mesh = builder.take();

  const double angle = 2 * std::numbers::pi / s.per_turn;
  Repetition rep = screw_repetition(
      "steps", 360.0 / s.per_turn, s.rise, s.steps,
      "step i: the wedge at angles [i, i+1] * 360/steps_per_turn degrees and heights [(i+1)*rise - step_thickness, "
      "(i+1)*rise], fused to the column; count = steps");
  const double z0 = s.bottom(0), z1 = s.top(0);
  rep.measure = measure_unit(mesh, [&](const Vec3& x) {
    const double a = std::atan2(x.y(), x.x());
    return a >= -1e-9 && a <= angle + 1e-9 && x.z() >= z0 - 1e-9 && x.z() <= z1 + 1e-9;
  });
  const nlohmann::json notes = {
      {"description", "spiral stairs: wedge steps fused to a central prism column, counter-clockwise going up"},
      {"column_sides", fine / s.detail},
      {"column_height", s.height}};
  return finish_asset(fmt::format("spiral_stairs_{}", s.steps), p, std::move(mesh), {rep}, nullptr, notes);
}

}  // namespace dg::assets
