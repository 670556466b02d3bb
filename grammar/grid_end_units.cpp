#include "grammar/grid_end_units.h"

#include "geometry/same_surface.h"
#include "geometry/slab_cut.h"
#include "geometry/submesh.h"
#include "geometry/topology.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <utility>

namespace dg {
namespace {

// Largest angle between a face's normal and the direction for the face to count as lying across
// it (detected motions of a turned model carry that much noise in their direction).
constexpr double kAcrossDegrees = 2.0;

// The triangles of `mesh` that do not lie in the plane d . x = offset: a face lies in it when its
// corners lie within `tolerance` of the plane, or when its normal is within kAcrossDegrees of +-d
// and its centroid within `tolerance` of the plane, plus what that tilt moves its far corner.
TriangleMesh without_faces_on(const TriangleMesh& mesh, const Vec3& d, double offset, double tolerance) {
  const double min_cos = std::cos(kAcrossDegrees * std::numbers::pi / 180.0);
  const double tilt = std::sin(kAcrossDegrees * std::numbers::pi / 180.0);
  std::vector<std::size_t> kept;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    const Vec3 area_vector = mesh.area_vector(t);
    const Vec3 centroid = (a + b + c) / 3.0;
    const double reach = std::max({(a - centroid).norm(), (b - centroid).norm(), (c - centroid).norm()});
    const bool across = area_vector.norm() > 0.0 && std::abs(area_vector.normalized().dot(d)) >= min_cos;
    const bool corners_in = std::max({std::abs(d.dot(a) - offset), std::abs(d.dot(b) - offset), std::abs(d.dot(c) - offset)}) <= tolerance;
    const bool tilted_in = across && std::abs(d.dot(centroid) - offset) <= tolerance + tilt * reach;
    if (!corners_in && !tilted_in) kept.push_back(t);
  }
  return submesh(mesh, kept);
}

// Whether `a` and `b` are the same surface within `tolerance`, their areas within `same_area`
// of each other (relative).
bool same_part(const TriangleMesh& a, const TriangleMesh& b, double tolerance, double same_area = kSameSlabArea) {
  const double area_a = a.area(), area_b = b.area();
  if (area_a <= 0.0 || std::abs(area_a - area_b) > same_area * std::max(area_a, area_b)) return false;
  return same_surface(a, b, tolerance);
}

// Own parts of a unit (connected components lying wholly in its slab) must make up at least this
// share of its surface for copies of them beyond the planes to count as units. A storey's small
// window on a plain wall band is 8 to 10 % of it (the Kenney town house: 7.9 %); a footbridge's
// post beside a metre of deck and handrail, 5.5 %, is too little to tell a unit by: its copies
// run on past the piers, and the posts would hide the spans.
constexpr double kOwnPartsShare = 0.07;

// `mesh` with its material indices replaced by their classes (`classes` empty: materials not
// matched, so dropped).
TriangleMesh with_material_classes(TriangleMesh mesh, std::span<const std::uint32_t> classes) {
  if (classes.empty()) mesh.materials.clear();
  for (std::uint32_t& m : mesh.materials) m = classes[m];
  return mesh;
}

// The connected parts (of `parts`) lying wholly in the repeated unit's slab, within `tolerance`.
std::vector<std::size_t> unit_parts(const GridDirection& direction, const MeshAlong& parts, double tolerance) {
  const double unit_lo = direction.cut + direction.head_units * direction.pitch, unit_hi = unit_lo + direction.pitch;
  std::vector<std::size_t> own;
  for (std::size_t c = 0; c < parts.part_triangles.size(); ++c)
    if (parts.part_spans[c].first >= unit_lo - tolerance && parts.part_spans[c].second <= unit_hi + tolerance) own.push_back(c);
  return own;
}

// Units beyond a direction's planes, past the `head` and `tail` units counted so far, whose own
// parts are copies of the repeated unit's though their slabs are not (a colonnade's end columns,
// under the ends of its beam and steps): the walk goes outward at each end while every part in
// `own` (unit_parts: lying wholly in the repeated unit's slab, of area `unit_area`) has a copy
// moved by the motion's power to that slab (centroids within `tolerance`, the same surface, the
// same area). Nothing when those parts make up less than kOwnPartsShare of the slab. Returns the
// units found before the head and after the tail.
std::pair<int, int> units_by_own_parts(const GridDirection& direction, const TriangleMesh& mesh, const MeshAlong& parts,
                                       const std::vector<std::size_t>& own, double tolerance,
                                       std::span<const std::uint32_t> material_classes, double unit_area, int head, int tail) {
  const Vec3& d = direction.direction;
  const int unit = direction.head_units;  // the repeated unit's slab
  double own_area = 0.0;
  for (std::size_t c : own) own_area += parts.part_areas[c];
  if (own.empty() || own_area < kOwnPartsShare * unit_area) return {0, 0};
  auto part_mesh = [&](std::size_t c) { return with_material_classes(submesh(mesh, parts.part_triangles[c]), material_classes); };
  std::map<std::size_t, TriangleMesh> own_meshes;
  for (std::size_t c : own) own_meshes.emplace(c, part_mesh(c));
  // Whether part c moved by `motion` is a part of the mesh.
  auto has_copy = [&](std::size_t c, const RigidTransform& motion) {
    const Vec3 centre = motion.apply(parts.part_centroids[c]);
    const double s = d.dot(centre);
    auto it = std::lower_bound(parts.parts_by_position.begin(), parts.parts_by_position.end(),
                               std::make_pair(s - tolerance, std::size_t{0}));
    for (; it != parts.parts_by_position.end() && it->first <= s + tolerance; ++it)
      if ((parts.part_centroids[it->second] - centre).norm() <= tolerance &&
          same_part(transformed(own_meshes.at(c), motion), part_mesh(it->second), tolerance))
        return true;
    return false;
  };
  auto copied_to = [&](int k) {
    const RigidTransform motion = power(direction.motion, k - unit);
    return std::all_of(own.begin(), own.end(), [&](std::size_t c) { return has_copy(c, motion); });
  };
  int before = 0, after = 0;
  while (copied_to(-head - before - 1)) ++before;
  while (copied_to(direction.count + tail + after)) ++after;
  return {before, after};
}

// The flat regions of `along` lying wholly between the planes d . x = lo and hi (more than
// `margin` from both).
std::vector<std::size_t> regions_between(const MeshAlong& along, double lo, double hi, double margin) {
  std::vector<std::size_t> inside;
  auto it = std::upper_bound(along.regions_by_start.begin(), along.regions_by_start.end(),
                             std::make_pair(lo + margin, std::numeric_limits<std::size_t>::max()));
  for (; it != along.regions_by_start.end() && it->first < hi - margin; ++it)
    if (along.region_spans[it->second].second < hi - margin) inside.push_back(it->second);
  return inside;
}

// Units beyond a direction's planes, past the `head` and `tail` units counted so far, whose own
// flat faces are copies of the repeated unit's though their slabs are not, as units_by_own_parts
// does with connected parts, for a unit with no part of its own (every part runs on across its
// planes): a straight stair's top step, whose tread is a copy though the end of the stair lies
// in its slab. Own flat faces: the flat regions of `along` lying wholly between the unit's
// planes and not across the direction (a tread, not a floor plate under every storey, which
// every slab has whatever else it holds, nor the sides every plane crosses), at least
// kOwnPartsShare of the slab's area `unit_area`.
std::pair<int, int> units_by_own_faces(const GridDirection& direction, const TriangleMesh& mesh, const MeshAlong& along,
                                       double tolerance, double unit_area, int head, int tail) {
  const int unit = direction.head_units;
  const double margin = 1e-3 * tolerance;
  auto lo = [&](int k) { return direction.cut + k * direction.pitch; };
  const std::vector<std::size_t> own = regions_between(along, lo(unit), lo(unit + 1), margin);
  double own_area = 0.0;
  for (std::size_t r : own) own_area += along.flat_regions[r].area;
  if (own.empty() || own_area < kOwnPartsShare * unit_area) return {0, 0};
  // Whether every own flat face of the unit, moved to slab k, is a flat face there.
  auto copied_to = [&](int k) {
    const RigidTransform motion = power(direction.motion, k - unit);
    const std::vector<std::size_t> found = regions_between(along, lo(k), lo(k + 1), margin);
    return std::all_of(own.begin(), own.end(), [&](std::size_t r) {
      const FlatRegion moved = moved_region(along.flat_regions[r], mesh, motion);
      return std::any_of(found.begin(), found.end(),
                         [&](std::size_t f) { return same_flat_region(moved, along.flat_regions[f], tolerance); });
    });
  };
  int before = 0, after = 0;
  while (copied_to(-head - before - 1)) ++before;
  while (copied_to(direction.count + tail + after)) ++after;
  return {before, after};
}

}  // namespace

MeshAlong measure_along(const TriangleMesh& mesh, const Vec3& direction, std::span<const std::uint32_t> material_classes) {
  const Vec3& d = direction;
  MeshAlong along;
  along.lowest = std::numeric_limits<double>::infinity();
  along.highest = -along.lowest;
  for (const Vec3& x : mesh.positions) {
    along.lowest = std::min(along.lowest, d.dot(x));
    along.highest = std::max(along.highest, d.dot(x));
  }
  std::size_t count = 0;
  const std::vector<std::uint32_t> component = triangle_components(mesh, &count);
  along.part_triangles.resize(count);
  along.part_centroids.assign(count, Vec3::Zero());
  along.part_areas.assign(count, 0.0);
  along.part_spans.assign(count, {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()});
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::uint32_t c = component[t];
    along.part_triangles[c].push_back(t);
    const auto [a, b, e] = mesh.corners(t);
    const double area = 0.5 * mesh.area_vector(t).norm();
    along.part_centroids[c] += area * (a + b + e) / 3.0;
    along.part_areas[c] += area;
    const double sa = d.dot(a), sb = d.dot(b), se = d.dot(e);
    along.part_spans[c].first = std::min({along.part_spans[c].first, sa, sb, se});
    along.part_spans[c].second = std::max({along.part_spans[c].second, sa, sb, se});
  }
  for (std::size_t c = 0; c < count; ++c) {
    if (along.part_areas[c] > 0.0) along.part_centroids[c] /= along.part_areas[c];
    along.parts_by_position.emplace_back(d.dot(along.part_centroids[c]), c);
  }
  std::sort(along.parts_by_position.begin(), along.parts_by_position.end());
  const double across_cos = std::cos(kAcrossDegrees * std::numbers::pi / 180.0);
  for (FlatRegion& region : flat_regions(mesh, std::vector<char>(mesh.triangles.size(), 1), FlatJoin::sharing_corners)) {
    if (std::abs(region.normal.dot(d)) >= across_cos) continue;
    region.material = material_classes.empty() ? 0 : material_classes[region.material];
    std::pair<double, double> span{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    for (std::uint32_t t : region.triangles)
      for (std::uint32_t v : mesh.triangles[t]) {
        span.first = std::min(span.first, d.dot(mesh.positions[v]));
        span.second = std::max(span.second, d.dot(mesh.positions[v]));
      }
    along.regions_by_start.emplace_back(span.first, along.flat_regions.size());
    along.region_spans.push_back(span);
    along.flat_regions.push_back(std::move(region));
  }
  std::sort(along.regions_by_start.begin(), along.regions_by_start.end());
  return along;
}

int count_end_units(GridDirection& direction, const TriangleMesh& mesh, double tolerance,
                    std::span<const std::uint32_t> material_classes, const MeshAlong* measured) {
  const Vec3& d = direction.direction;
  const double p = direction.pitch, start = direction.cut;
  const double snap = 1e-6 * tolerance;
  std::optional<MeshAlong> measured_here;
  if (!measured) measured = &measured_here.emplace(measure_along(mesh, d, material_classes));
  const double lowest = measured->lowest, highest = measured->highest;

  auto by_class = [&](TriangleMesh cut) { return with_material_classes(std::move(cut), material_classes); };
  // Faces in the model's first and last plane across the direction (the end caps of a plate
  // that the units stand on) are no part of a unit: slabs that reach them are compared without.
  auto without_caps = [&](const TriangleMesh& part) {
    return without_faces_on(without_faces_on(part, d, lowest, tolerance), d, highest, tolerance);
  };
  // Slab k lies between start + k p and start + (k + 1) p; each walk outward compares a slab with
  // the one it compared before, so cut meshes are kept per slab (and, for the slabs that reach
  // the model's ends, without the end caps).
  const SlabTable slabs(mesh, d, start, p);
  auto reaches_end = [&](int k) { return start + k * p <= lowest + tolerance || start + (k + 1) * p >= highest - tolerance; };
  std::map<int, TriangleMesh> meshes, bare_meshes;
  auto slab = [&](int k) -> const TriangleMesh& {
    auto [it, added] = meshes.try_emplace(k);
    if (added) it->second = by_class(slabs.mesh(k, snap));
    return it->second;
  };
  auto bare = [&](int k) -> const TriangleMesh& {
    if (!reaches_end(k)) return slab(k);
    auto [it, added] = bare_meshes.try_emplace(k);
    if (added) it->second = without_caps(slab(k));
    return it->second;
  };
  // Whether slab k, moved by the motion, is slab k + 1, as it is (the slab table's areas reject
  // most slabs before they are cut) or, where one reaches an end of the model, without the end
  // caps; or else both without the faces in the plane at `outer` (in slab k + 1's place), the
  // outer plane of the slab beyond the units: where another part begins right at a unit's end
  // (the side of a bookshelf against its last book), the slab holds that part's face.
  auto copies_next = [&](int k, double outer) {
    const double a = slabs.area(k), b = slabs.area(k + 1);
    const bool same_table_area = a > 0.0 && std::abs(a - b) <= kSameSlabArea * std::max(a, b);
    if (same_table_area && same_surface(transformed(slab(k), direction.motion), slab(k + 1), tolerance)) return true;
    const bool at_end = reaches_end(k) || reaches_end(k + 1);
    const TriangleMesh moved = transformed(bare(k), direction.motion);
    if (at_end && same_part(moved, bare(k + 1), tolerance)) return true;
    // (A face in a plane may also fall in the slab on the plane's other side when the slabs are
    // cut, against the slab table's areas; slivers the cut leaves at the plane go too.) Meshes
    // that lose nothing were compared above, unless the table's areas kept them apart.
    const TriangleMesh open_moved = without_faces_on(moved, d, outer, tolerance);
    const TriangleMesh open_next = without_faces_on(bare(k + 1), d, outer, tolerance);
    const bool stripped =
        open_moved.triangles.size() < moved.triangles.size() || open_next.triangles.size() < bare(k + 1).triangles.size();
    if (!stripped && (same_table_area || at_end)) return false;
    return same_part(open_moved, open_next, tolerance);
  };
  int head = 0, tail = 0;
  while (copies_next(-head - 1, start - head * p)) ++head;
  while (copies_next(direction.count + tail - 1, start + (direction.count + tail + 1) * p)) ++tail;
  // A unit split between the ends (a row of lockers cut between their handles): the part before
  // the first plane is the end of a unit and the part after the last plane its beginning, the two
  // one pitch long together. It counts as a unit kept in the head.
  const double first = start - head * p, last = start + (direction.count + tail) * p;
  const double before = first - lowest, after = highest - last;
  bool split = false;
  if (before > tolerance && after > tolerance && std::abs(before + after - p) <= tolerance) {
    // The unit's part that a part beyond the planes copies, from `from` over `length`, without
    // the faces in its plane at `boundary` (where the row's objects meet back to back).
    auto unit_part = [&](double from, double length, double boundary) {
      return without_faces_on(by_class(SlabTable(mesh, d, from, length).mesh(0, snap)), d, boundary, tolerance);
    };
    const TriangleMesh head_moved = without_faces_on(transformed(bare(-head - 1), direction.motion), d, lowest + p, tolerance);
    const TriangleMesh tail_moved =
        without_faces_on(transformed(bare(direction.count + tail), direction.motion.inverse()), d, highest - p, tolerance);
    // The parts end at the model's end faces, the unit's at planes across the detected motion: on
    // a turned model the two lean apart by the motion's noise, leaving slivers of the sides.
    constexpr double kSplitArea = 1e-2;
    split = same_part(head_moved, unit_part(lowest + p, before, lowest + p), tolerance, kSplitArea) &&
            same_part(tail_moved, unit_part(last - p, after, highest - p), tolerance, kSplitArea);
  }
  // Units beyond whose own parts are copies of the repeated unit's, though the slabs are not.
  // Only a unit that repeats as a whole slab at least once may be counted so: two boxes on a
  // sphere that every plane between them crosses are no row (copying a slab would copy part of
  // the sphere).
  if (!split && direction.count + head + tail >= 2) {
    // A unit with parts of its own is told by them; one whose parts all run on across its
    // planes (a stair's body and balusters) by its own flat faces.
    const std::vector<std::size_t> own = unit_parts(direction, *measured, tolerance);
    const double unit_area = slabs.area(direction.head_units);
    const auto [more_head, more_tail] =
        own.empty() ? units_by_own_faces(direction, mesh, *measured, tolerance, unit_area, head, tail)
                    : units_by_own_parts(direction, mesh, *measured, own, tolerance, material_classes, unit_area, head, tail);
    head += more_head;
    tail += more_tail;
  }
  const int kept_in_head = head + (split ? 1 : 0);
  direction.split_unit = direction.split_unit || split;
  direction.cut -= kept_in_head * p;
  direction.count += kept_in_head + tail;
  direction.head_units += kept_in_head;
  direction.tail_units += tail;
  return kept_in_head + tail;
}

}  // namespace dg
