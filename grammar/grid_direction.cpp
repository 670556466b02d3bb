#include "grammar/grid_direction.h"

#include "grammar/asymmetric_spans.h"
#include "grammar/grid_end_units.h"
#include "grammar/sliding_units.h"
#include "geometry/slab_cut.h"
#include "symmetry/symmetric_region.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace dg {
namespace {

// Sorted, merged intervals of the line where a cut plane may not go.
class Blocked {
 public:
  void add(double lo, double hi) { intervals_.emplace_back(lo, hi); }
  void finish() {
    std::sort(intervals_.begin(), intervals_.end());
    std::vector<std::pair<double, double>> merged;
    for (const auto& iv : intervals_) {
      if (!merged.empty() && iv.first <= merged.back().second)
        merged.back().second = std::max(merged.back().second, iv.second);
      else
        merged.push_back(iv);
    }
    intervals_ = std::move(merged);
  }
  /// Distance from s to the nearest blocked interval (0 inside one, infinity when none).
  double clearance(double s) const {
    auto it = std::upper_bound(intervals_.begin(), intervals_.end(), std::make_pair(s, std::numeric_limits<double>::infinity()));
    double distance = std::numeric_limits<double>::infinity();
    if (it != intervals_.end()) distance = std::min(distance, it->first - s);
    if (it != intervals_.begin()) distance = std::min(distance, std::max(0.0, s - std::prev(it)->second));
    return distance;
  }
  bool contains(double s) const {
    auto it = std::upper_bound(intervals_.begin(), intervals_.end(), std::make_pair(s, std::numeric_limits<double>::infinity()));
    return it != intervals_.begin() && std::prev(it)->second >= s;
  }

 private:
  std::vector<std::pair<double, double>> intervals_;
};

// Cells by their position along a direction, to count the cells of a slab and how many of them
// lie outside the symmetric region.
class SlabCells {
 public:
  void add(double s, bool symmetric) { cells_.emplace_back(s, symmetric ? 0 : 1); }
  void finish() {
    std::sort(cells_.begin(), cells_.end());
    asymmetric_before_.assign(cells_.size() + 1, 0);
    for (std::size_t i = 0; i < cells_.size(); ++i) asymmetric_before_[i + 1] = asymmetric_before_[i] + cells_[i].second;
  }
  /// (asymmetric cells, all cells) with position strictly between lo and hi.
  std::pair<std::size_t, std::size_t> count(double lo, double hi) const {
    const auto begin = std::upper_bound(cells_.begin(), cells_.end(), std::make_pair(lo, 2));
    const auto end = std::lower_bound(cells_.begin(), cells_.end(), std::make_pair(hi, 0));
    if (end <= begin) return {0, 0};
    const auto b = static_cast<std::size_t>(begin - cells_.begin()), e = static_cast<std::size_t>(end - cells_.begin());
    return {asymmetric_before_[e] - asymmetric_before_[b], e - b};
  }

 private:
  std::vector<std::pair<double, int>> cells_;
  std::vector<std::size_t> asymmetric_before_;
};

// Surface area of `mesh` in each unit slab of `direction`: entry k - 1 for slab k = 1 .. count,
// between the planes cut + (k - 1) pitch and cut + k pitch (model units^2).
std::vector<double> unit_slab_areas(const TriangleMesh& mesh, const GridDirection& direction) {
  std::vector<double> areas(static_cast<std::size_t>(direction.count), 0.0);
  const Vec3& d = direction.direction;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    std::array<double, 3> s{d.dot(a), d.dot(b), d.dot(c)};
    std::sort(s.begin(), s.end());
    const double area = 0.5 * mesh.area_vector(t).norm();
    const int first = std::max(1, static_cast<int>(std::floor((s[0] - direction.cut) / direction.pitch)) + 1);
    const int last = std::min(direction.count, static_cast<int>(std::floor((s[2] - direction.cut) / direction.pitch)) + 1);
    for (int k = first; k <= last; ++k) {
      const double lo = direction.cut + (k - 1) * direction.pitch, hi = lo + direction.pitch;
      areas[static_cast<std::size_t>(k - 1)] += triangle_area_below(s[0], s[1], s[2], area, hi) - triangle_area_below(s[0], s[1], s[2], area, lo);
    }
  }
  return areas;
}

// Picks the repeated unit of a direction: the first slab of the longest run of slabs that are
// exact copies of the next, judged by the voxel cells (no asymmetric cell strictly inside,
// `half` the cells' half extent along the direction) and by the mesh (the same surface area,
// which also tells back-to-back duplicate faces, invisible to the cells, apart; a point cloud
// has no triangles, so its cells alone judge). The slabs
// before the run stay in the head and those after it in the tail, so damage in one unit (a fin,
// a doubled face, a differing end stake) is placed once instead of copied. Without such a run
// the first slab stays the unit.
void choose_repeated_unit(GridDirection& direction, const SlabCells& slab_cells, double half, const TriangleMesh& mesh) {
  const std::vector<double> areas = unit_slab_areas(mesh, direction);
  auto copies_next = [&](int k) {  // slab k equals slab k + 1
    const double a = areas[static_cast<std::size_t>(k - 1)], b = areas[static_cast<std::size_t>(k)];
    return slab_cells.count(direction.cut + (k - 1) * direction.pitch + half, direction.cut + k * direction.pitch - half).first == 0 &&
           std::abs(a - b) <= kSameSlabArea * std::max(a, b);
  };
  int best_first = 0, best_last = -1;  // run of slabs k = first .. last, each equal to slab k + 1
  for (int first = 1; first < direction.count;) {
    int last = first - 1;
    while (last + 1 < direction.count && copies_next(last + 1)) ++last;
    if (last - first > best_last - best_first) best_first = first, best_last = last;
    first = last + 2;
  }
  if (best_last < best_first) return;
  direction.head_units = best_first - 1;
  direction.tail_units = direction.count - (best_last + 1);
}

// Chains with the most units between planes whose copies beyond the planes are counted (in the
// order of the rest of the ranking) when the best of them has any, or, one per stretch of phases,
// when the model leaves room for another unit beyond the best chain's (the phase decides whether
// whole copies remain at the ends: a chain of rings reaches its end rings at one phase).
constexpr std::size_t kLongestChainsCounted = 16;
// With such room, further chains with up to kShorterChainLevels fewer units between planes are
// counted too, in ranking order, one per stretch of phases and kShorterChainsCounted in all (the
// chains as long as the best once used them up): a phase whose planes cross thin dividers fits
// fewer units between planes than one through the cells, but may reach whole copies at both ends
// (a shelf's bottom and top rows, whose outer boards differ from its dividers; a bookshelf's
// first and last books, against its sides). Moving the phase loses at most the plane at each end.
constexpr int kShorterChainLevels = 2;
constexpr std::size_t kShorterChainsCounted = 6;

// What the search for one motion's chain of planes knows of the model: the motion, where cells
// block planes, the slabs' cells, the offsets the first plane may take, the planes holding faces.
struct MotionPlanes {
  const PreparedModel& prepared;
  const DirectionSearch& search;
  std::size_t symmetry_index = 0;
  bool points = false;  // a point cloud: no faces, no seams
  // A translation's generator is kept exact (no rotation noise from the detector's fit).
  RigidTransform motion{};
  Vec3 t = Vec3::Zero(), d = Vec3::UnitX();  // translation (a screw's slide) and its direction
  double pitch = 0.0;
  double half = 0.0;  // the cells' half extent along d
  std::vector<char> in_r{}, in_xi{};  // per cell: r-symmetric, symmetric
  // Where the planes after the first may not go (not r-symmetric), where the first may not go
  // (not symmetric, and later symmetric cells near asymmetry on both sides), where the plane
  // after the last may not go (outside the image of the r-symmetric area; filled only once a
  // chain may exist, see block_outside_image).
  Blocked forward{}, first_plane{}, backward{};
  SlabCells slab_cells{};
  double lowest = 0.0, highest = 0.0;  // the model's extent along d
  std::map<double, int> phases{};  // offset of the planes in [0, pitch) (up to rounding) -> vertices on a plane there
  std::vector<double> vertex_phases{};  // the phases holding vertices, ascending
  std::vector<double> face_planes{};    // positions of the planes that hold a whole face, ascending
  // The mesh measured along d for counting end units, once the first chain needs it.
  mutable std::optional<MeshAlong> along{};
};

// How far from a plane a face's corners may lie for the plane to hold the face (rounding).
double face_plane_tolerance(const MotionPlanes& planes) { return 1e-6 * planes.prepared.surface.eps(); }

// Runs found before along this motion keep their planes and half a pitch around them.
void block_taken(const MotionPlanes& planes, Blocked& blocked) {
  for (const auto& [lo, hi] : planes.search.taken) blocked.add(lo - 0.5 * planes.pitch, hi + 0.5 * planes.pitch);
}

// The planes of `symmetry`'s motion across the prepared model, or nothing when the motion has no
// translation or the model cannot hold search.min_repeats of it.
std::optional<MotionPlanes> motion_planes(const PreparedModel& prepared, const DetectedSymmetry& symmetry,
                                          std::size_t symmetry_index, const DirectionSearch& search) {
  const VoxelSurface& surface = prepared.surface;
  const ScrewParameters screw = screw_parameters(symmetry.transform);
  const Vec3 t = symmetry.kind == "translation" ? symmetry.transform.translation : screw.slide * screw.axis;
  const double pitch = t.norm();
  // Copies of the unit beyond the first and last plane count, so n units may span only a little
  // more than n - 1 pitches (two layers of crates with a gap between them).
  const int spanned_pitches = search.copy_tolerance > 0.0 ? search.min_repeats - 1 : search.min_repeats;
  if (pitch <= 0.0 || !spans_pitches(prepared.cleaning.bounds, t, spanned_pitches)) return std::nullopt;
  MotionPlanes planes{.prepared = prepared, .search = search};
  planes.symmetry_index = symmetry_index;
  planes.points = prepared.model.is_point_cloud();
  planes.motion = symmetry.kind == "translation" ? RigidTransform{Mat3::Identity(), t} : symmetry.transform;
  planes.t = t;
  planes.pitch = pitch;
  const Vec3 d = planes.d = t / pitch;
  planes.half = 0.5 * surface.eps() * (std::abs(d.x()) + std::abs(d.y()) + std::abs(d.z()));

  planes.in_r.assign(surface.cell_count(), 0);
  planes.in_xi.assign(surface.cell_count(), 0);
  for (std::uint32_t c : symmetry.region.r_symmetric_cells) planes.in_r[c] = 1;
  for (std::uint32_t c : symmetry.region.symmetric_cells) planes.in_xi[c] = 1;
  for (std::uint32_t c = 0; c < surface.cell_count(); ++c) {
    const double s = d.dot(surface.centre(c));
    if (!planes.in_r[c]) planes.forward.add(s - planes.half, s + planes.half);
    if (!planes.in_xi[c]) planes.first_plane.add(s - planes.half, s + planes.half);
    planes.slab_cells.add(s, planes.in_xi[c] != 0);
  }
  block_taken(planes, planes.forward);
  block_taken(planes, planes.first_plane);
  planes.forward.finish();
  planes.first_plane.finish();
  planes.slab_cells.finish();

  // Candidate offsets of the first plane, taken modulo the pitch: a fine sampling of one period
  // plus every vertex coordinate of a mesh (cuts through existing seams need no new vertices; a
  // point cloud has no seams, only its extent counts).
  planes.lowest = std::numeric_limits<double>::infinity();
  planes.highest = -planes.lowest;
  std::map<double, int> vertex_offsets;
  for (const Vec3& p : planes.points ? prepared.model.cloud.positions : prepared.model.mesh.positions) {
    const double s = d.dot(p);
    if (!planes.points) ++vertex_offsets[s];
    planes.lowest = std::min(planes.lowest, s);
    planes.highest = std::max(planes.highest, s);
  }
  const double step = std::min(surface.eps() / 4.0, pitch / 64.0);
  for (double phase = 0.0; phase < pitch; phase += step) planes.phases.emplace(phase, 0);
  // Vertices whose phases differ by rounding alone (the seams of a turned model) share one: a
  // plane there passes through all of them, within the cuts' snapping distance.
  const double same_phase = 1e-7 * surface.eps();
  std::vector<std::pair<double, int>> at_vertices;
  for (const auto& [s, n] : vertex_offsets) {
    const double phase = std::fmod(s - planes.lowest, pitch);
    at_vertices.emplace_back(phase > pitch - same_phase ? phase - pitch : phase, n);
  }
  std::sort(at_vertices.begin(), at_vertices.end());
  for (std::size_t i = 0; i < at_vertices.size();) {
    std::size_t end = i + 1;
    while (end < at_vertices.size() && at_vertices[end].first - at_vertices[end - 1].first <= same_phase) ++end;
    double sum = 0.0;
    int vertices = 0;
    for (std::size_t j = i; j < end; ++j) sum += at_vertices[j].first, vertices += at_vertices[j].second;
    planes.phases[sum / static_cast<double>(end - i)] += vertices;
    i = end;
  }
  for (const auto& [phase, n] : planes.phases)
    if (n > 0) planes.vertex_phases.push_back(phase);

  // Planes that hold a whole face: a cut there would leave the face on either side by rounding.
  const TriangleMesh& mesh = prepared.model.mesh;
  const double in_plane = face_plane_tolerance(planes);
  for (const Triangle& tri : mesh.triangles) {
    const double a = d.dot(mesh.positions[tri[0]]), b = d.dot(mesh.positions[tri[1]]), c = d.dot(mesh.positions[tri[2]]);
    if (std::max({a, b, c}) - std::min({a, b, c}) <= in_plane) planes.face_planes.push_back(a);
  }
  std::sort(planes.face_planes.begin(), planes.face_planes.end());
  return planes;
}

// Stretches of phases between those of vertices: index of the first vertex phase at or above
// `phase`, doubled, plus one when the phase is a vertex phase.
std::ptrdiff_t phase_stretch(const MotionPlanes& planes, double phase) {
  const auto at = std::lower_bound(planes.vertex_phases.begin(), planes.vertex_phases.end(), phase);
  return 2 * (at - planes.vertex_phases.begin()) + (at != planes.vertex_phases.end() && *at == phase ? 1 : 0);
}

// Every slab between planes `first` + k pitch, k < `slabs`, maps onto the next: (almost) no
// asymmetric cell strictly inside.
bool slabs_repeat(const MotionPlanes& planes, double first, int slabs) {
  for (int k = 0; k < slabs; ++k) {
    const auto [asymmetric_cells, cells] =
        planes.slab_cells.count(first + k * planes.pitch + planes.half, first + (k + 1) * planes.pitch - planes.half);
    if (static_cast<double>(asymmetric_cells) > planes.search.max_slab_asymmetry * static_cast<double>(cells)) return false;
  }
  return true;
}

// Whether the plane at `plane` holds a whole face.
bool holds_a_face(const MotionPlanes& planes, double plane) {
  const double in_plane = face_plane_tolerance(planes);
  const auto it = std::lower_bound(planes.face_planes.begin(), planes.face_planes.end(), plane - in_plane);
  return it != planes.face_planes.end() && *it <= plane + in_plane;
}

// Surface cells crossed by the planes `first` + k pitch, k = 0 .. `count` (the seams' size), or
// nothing when one of them holds a face.
std::optional<std::size_t> seam_cells(const MotionPlanes& planes, double first, int count) {
  std::size_t crossed = 0;
  for (int k = 0; k <= count; ++k) {
    const double plane = first + k * planes.pitch;
    if (holds_a_face(planes, plane)) return std::nullopt;
    crossed += planes.slab_cells.count(plane - planes.half, plane + planes.half).second;
  }
  return crossed;
}

// The chain starting at `first` with `count` units, its first unit the repeated one.
GridDirection unsettled(const MotionPlanes& planes, double first, int count) {
  return GridDirection{.motion = planes.motion, .translation = planes.t, .direction = planes.d, .pitch = planes.pitch,
                       .cut = first, .count = count, .symmetry = planes.symmetry_index};
}

// With a copy tolerance, the copies of the direction's unit beyond its planes join its count.
void count_copies_beyond(const MotionPlanes& planes, GridDirection& direction) {
  if (planes.search.copy_tolerance <= 0.0) return;
  const TriangleMesh& mesh = planes.prepared.model.mesh;
  if (!planes.along) planes.along = measure_along(mesh, planes.d, planes.prepared.material_classes);
  count_end_units(direction, mesh, planes.search.copy_tolerance, planes.prepared.material_classes, &*planes.along);
}

// The chain starting at `first` with `count` units, its repeated unit chosen and the copies
// beyond its planes counted.
GridDirection settled(const MotionPlanes& planes, double first, int count) {
  GridDirection direction = unsettled(planes, first, count);
  choose_repeated_unit(direction, planes.slab_cells, planes.half, planes.prepared.model.mesh);
  count_copies_beyond(planes, direction);
  return direction;
}

// Whether the model's extent along the direction leaves room for more than `count` units: units
// counted beyond the planes need not lie between them, so n units with gaps between them span
// n - 1 pitches and a little more (three crates in a row, 0.05 apart at a pitch of 0.65).
bool room_for_another_unit(const MotionPlanes& planes, int count) {
  return count * planes.pitch + planes.half < planes.highest - planes.lowest;
}

// A candidate chain of planes.
struct Chain {
  double first = 0.0;
  double phase = 0.0;  // of its planes, in [0, pitch) from the model's lowest point
  int count = 0;
  double clearance = -1.0;
  std::size_t crossed = 0;
  int vertices = 0;
};

// A chain of more than `more_than` units that are copies side by side, though no chain of them
// lies between planes in the r-symmetric area: the area between copies can be eroded by r where
// one copy's outer boards lie close to the next copy's asymmetric end (a shelf of two columns:
// its middle divider is thinner than 2r, and the second column maps beyond the model), or be
// broken up where thin parts cross the voxels obliquely (a turned shelf's dividers). Seeds are
// runs of slabs whose cells map onto the next slab's (slabs_repeat) at planes that hold no face;
// each seed's first slab becomes the unit and its copies are verified on the mesh and counted as
// in count_end_units. Seeds are ranked by more slabs, then more vertices on the planes (cuts
// through existing seams leave copies cut alike), then smaller seams; one per stretch of phases
// whose unit does not only slide along itself is verified, up to kShorterChainsCounted of them,
// and the most units wins.
std::optional<GridDirection> copied_chain(const MotionPlanes& planes, int more_than) {
  const DirectionSearch& search = planes.search;
  if (planes.points || search.copy_tolerance <= 0.0) return std::nullopt;
  const double pitch = planes.pitch, half = planes.half;
  auto maps_onto_next = [&](double first) {  // a slab with surface that maps onto the next
    return planes.slab_cells.count(first + half, first + pitch - half).second > 0 && slabs_repeat(planes, first, 1);
  };
  std::vector<Chain> seeds;
  for (const auto& [phase, vertices] : planes.phases)
    for (double first = planes.lowest + phase - pitch; first <= planes.highest; first += pitch) {
      if (!maps_onto_next(first) || maps_onto_next(first - pitch)) continue;
      int count = 2;  // slabs: those that map onto the next, and the last image
      while (maps_onto_next(first + (count - 1) * pitch)) ++count;
      if (count < search.min_repeats || count <= more_than) continue;
      if (const std::optional<std::size_t> crossed = seam_cells(planes, first, count))
        seeds.push_back(Chain{first, phase, count, 0.0, *crossed, vertices});
    }
  std::stable_sort(seeds.begin(), seeds.end(), [](const Chain& a, const Chain& b) {
    if (a.count != b.count) return a.count > b.count;
    return a.vertices != b.vertices ? a.vertices > b.vertices : a.crossed < b.crossed;
  });
  std::set<std::ptrdiff_t> stretches;
  std::size_t verified = 0;
  std::optional<GridDirection> best;
  const TriangleMesh& mesh = planes.prepared.model.mesh;
  for (const Chain& seed : seeds) {
    // A seed's slabs bound its copies: none of the rest can reach further.
    if (verified == kShorterChainsCounted || (best && best->count >= seed.count)) break;
    // The unit stays the seed's first slab however far the copies reach, so an extrusion is told
    // before the costly check.
    if (!stretches.insert(phase_stretch(planes, seed.phase)).second || unit_only_slides(mesh, unsettled(planes, seed.first, 1)))
      continue;
    ++verified;
    // The copies are found beyond the seed's unit; those that also repeat cell for cell become
    // repeated units instead of being kept once.
    GridDirection direction = unsettled(planes, seed.first, 1);
    count_copies_beyond(planes, direction);
    choose_repeated_unit(direction, planes.slab_cells, half, mesh);
    if (direction.count >= search.min_repeats && direction.count > more_than && (!best || direction.count > best->count))
      best = std::move(direction);
  }
  return best;
}

// A quick test whether any run of min_repeats units may exist, before the costly parts (the image
// of the r-symmetric area, the asymmetry near the first plane): their tests only take planes
// away, so without such a run here there is none below.
bool may_repeat(const MotionPlanes& planes) {
  const int min_repeats = planes.search.min_repeats;
  for (const auto& [phase, vertices] : planes.phases)
    for (double first = planes.lowest + phase; first <= planes.highest; first += planes.pitch) {
      if (planes.first_plane.contains(first)) continue;
      int free = 1;
      while (free < min_repeats && first + free * planes.pitch <= planes.highest &&
             !planes.forward.contains(first + free * planes.pitch))
        ++free;
      if (free == min_repeats && slabs_repeat(planes, first, min_repeats - 1)) return true;
    }
  return false;
}

// Fills planes.backward (the plane after a chain's last unit must lie in the image of the
// r-symmetric area) and lets the first plane also cross symmetric cells near asymmetric ones
// (damage such as a fin) when all that asymmetry lies on one side of it: the r-neighbourhoods of
// the seams between copied units then occur in the exemplar, at the first plane (asymmetry above
// it: the head's top is a copy of the unit's top) or at the second (asymmetry below: the second
// unit's bottom is a copy of the first's).
void block_outside_image(MotionPlanes& planes, const DetectedSymmetry& symmetry) {
  const VoxelSurface& surface = planes.prepared.surface;
  std::vector<char> in_image(surface.cell_count(), 0);
  const CellMatcher matcher(surface, nullptr);
  // A cell lies in the image when its preimage does lie in the r-symmetric region (pulled back,
  // so a rotation's rounding to voxels leaves no holes in the image).
  const RigidTransform inverse = symmetry.transform.inverse();
  for (std::uint32_t c = 0; c < surface.cell_count(); ++c) {
    const std::int64_t preimage = matcher.image_cell(c, inverse);
    if (preimage >= 0 && planes.in_r[static_cast<std::size_t>(preimage)]) in_image[c] = 1;
  }
  const std::vector<PositionSpan> spans = asymmetric_spans(surface, planes.in_xi, planes.d, surface.r());
  const double half = planes.half;
  for (std::uint32_t c = 0; c < surface.cell_count(); ++c) {
    const double s = planes.d.dot(surface.centre(c));
    if (!in_image[c]) planes.backward.add(s - half, s + half);
    if (planes.in_xi[c] && !planes.in_r[c] && !spans[c].empty()) {
      const double lo = std::max(s - half, spans[c].lo - half), hi = std::min(s + half, spans[c].hi + half);
      if (lo <= hi) planes.first_plane.add(lo, hi);
    }
  }
  block_taken(planes, planes.backward);
  planes.backward.finish();
  planes.first_plane.finish();
}

// Every run of at least one unit between allowed planes (shorter ones may reach copies), its
// first unit outside every range in `sliding`.
std::vector<Chain> chains_between_planes(const MotionPlanes& planes, const std::vector<std::pair<double, double>>& sliding) {
  const double pitch = planes.pitch;
  auto excluded = [&](double first) {
    return std::any_of(sliding.begin(), sliding.end(),
                       [&](const auto& range) { return first < range.second && first + pitch > range.first; });
  };
  const double wanted_clearance = planes.prepared.surface.r();
  std::vector<Chain> chains;
  for (const auto& [phase, vertices] : planes.phases) {
    // Walk the planes lowest + phase + j * pitch across the model and find runs of allowed ones.
    for (double first = planes.lowest + phase; first <= planes.highest; first += pitch) {
      // Not a run start: blocked, or the run from the plane before includes this one.
      if (planes.first_plane.contains(first) || excluded(first) ||
          (first - pitch >= planes.lowest && !planes.first_plane.contains(first - pitch) && !planes.forward.contains(first) &&
           !excluded(first - pitch)))
        continue;
      int count = 1;
      while (!planes.forward.contains(first + count * pitch) && first + count * pitch <= planes.highest) ++count;
      // The plane after the last unit must lie in the image of the r-symmetric area.
      while (count > 0 && planes.backward.contains(first + count * pitch)) --count;
      // Every slab but the last maps onto the next.
      for (int k = 0; k + 1 < count; ++k)
        if (!slabs_repeat(planes, first + k * pitch, 1)) {
          count = k + 1;
          break;
        }
      if (count < 1) continue;
      const std::optional<std::size_t> crossed = seam_cells(planes, first, count);
      if (!crossed) continue;
      double clearance = wanted_clearance;
      clearance = std::min(clearance, planes.first_plane.clearance(first));
      for (int k = 1; k < count; ++k) clearance = std::min(clearance, planes.forward.clearance(first + k * pitch));
      clearance = std::min(clearance, planes.backward.clearance(first + count * pitch));
      chains.push_back(Chain{first, phase, count, clearance, *crossed, vertices});
    }
  }
  return chains;
}

// The best chain whose first unit lies outside every range in `sliding`. Ranking: more units
// between planes; then, when the best by the rest counts copies beyond its planes or leaves room
// for them (the phase decides whether whole copies remain at the ends), more units in all
// (kLongestChainsCounted, kShorterChainLevels); then more clearance (beyond rounding); then the
// smallest seams (fewest surface cells crossed by the planes); then planes through more existing
// vertices.
std::optional<GridDirection> best_chain(const MotionPlanes& planes, const std::vector<std::pair<double, double>>& sliding) {
  std::vector<Chain> chains = chains_between_planes(planes, sliding);
  if (chains.empty()) return std::nullopt;
  std::stable_sort(chains.begin(), chains.end(), [](const Chain& a, const Chain& b) {
    if (a.count != b.count) return a.count > b.count;
    if (std::abs(a.clearance - b.clearance) > 1e-12) return a.clearance > b.clearance;
    return a.crossed != b.crossed ? a.crossed < b.crossed : a.vertices > b.vertices;
  });
  const int longest = chains[0].count;
  if (longest < planes.search.min_repeats) return std::nullopt;
  GridDirection best = settled(planes, chains[0].first, longest);
  if (planes.search.copy_tolerance <= 0.0) return best;
  // Copies beyond the planes, or room for them: other phases may leave more units in all.
  const bool beyond = best.count > longest, room = room_for_another_unit(planes, best.count);
  // With room, one chain per stretch between vertex phases is counted: its planes cross the same
  // edges as any other chain's there.
  std::set<std::ptrdiff_t> stretches{phase_stretch(planes, chains[0].phase)};
  std::size_t longest_counted = 1, shorter_counted = 0;
  for (std::size_t i = 1; i < chains.size(); ++i) {
    const Chain& chain = chains[i];
    if (chain.count == longest) {
      if (longest_counted == kLongestChainsCounted ||
          (!beyond && (!room || !stretches.insert(phase_stretch(planes, chain.phase)).second)))
        continue;
      ++longest_counted;
    } else {
      if (!room || chain.count < longest - kShorterChainLevels || shorter_counted == kShorterChainsCounted ||
          !stretches.insert(phase_stretch(planes, chain.phase)).second)
        continue;
      ++shorter_counted;
    }
    GridDirection other = settled(planes, chain.first, chain.count);
    if (other.count > best.count) best = std::move(other);
  }
  return best;
}

// Whether a further run lies apart from the runs found before: units counted beyond its planes
// may not reach into one, and what lies between it and its neighbours must be mostly a different
// part (a gate between two stretches of fence), not more of the row that planes could not cross
// (brackets behind a radiator's fins).
bool apart_from_runs_before(const MotionPlanes& planes, const GridDirection& run) {
  const double lo = run.cut, hi = run.cut + run.count * planes.pitch;
  double below = -std::numeric_limits<double>::infinity(), above = std::numeric_limits<double>::infinity();
  for (const auto& [a, b] : planes.search.taken) {
    if (lo < b && hi > a) return false;
    if (b <= lo) below = std::max(below, b);
    if (a >= hi) above = std::min(above, a);
  }
  auto mostly_different = [&](double from, double to) {
    const auto [asymmetric_cells, cells] = planes.slab_cells.count(from, to);
    return 2 * asymmetric_cells > cells;
  };
  return (!std::isfinite(below) || mostly_different(below, lo)) && (!std::isfinite(above) || mostly_different(hi, above));
}

}  // namespace

bool spans_pitches(const BoundingBox& bounds, const Vec3& t, int pitches) {
  return t.cwiseAbs().dot(bounds.size()) >= pitches * t.squaredNorm();
}

std::optional<GridDirection> grid_direction(const PreparedModel& prepared, const DetectedSymmetry& symmetry,
                                            std::size_t symmetry_index, const DirectionSearch& search) {
  std::optional<MotionPlanes> planes = motion_planes(prepared, symmetry, symmetry_index, search);
  if (!planes) return std::nullopt;
  // A further run along the motion is a chain between planes (copies side by side are sought for
  // the first run only).
  const bool further = !search.taken.empty();
  if (!may_repeat(*planes)) return further ? std::nullopt : copied_chain(*planes, 0);
  block_outside_image(*planes, symmetry);

  // An extrusion cut at the pitch (a corridor reaching out of a map) is no row of units: its
  // chain is left out and the next best taken, a few times at most.
  constexpr int kSlidingChainsTried = 4;
  std::vector<std::pair<double, double>> sliding;
  std::optional<GridDirection> best = best_chain(*planes, sliding);
  if (!best) return further ? std::nullopt : copied_chain(*planes, 0);
  while (best && !planes->points && unit_only_slides(prepared.model.mesh, *best)) {
    if (static_cast<int>(sliding.size()) + 1 >= kSlidingChainsTried) return std::nullopt;
    sliding.emplace_back(best->cut, best->cut + best->count * planes->pitch);
    best = best_chain(*planes, sliding);
  }
  if (further) return best && apart_from_runs_before(*planes, *best) ? best : std::nullopt;
  // Room for another unit: copies side by side at another phase may reach further.
  if (best && room_for_another_unit(*planes, best->count))
    if (std::optional<GridDirection> copied = copied_chain(*planes, best->count)) best = std::move(copied);
  return best;
}

}  // namespace dg
