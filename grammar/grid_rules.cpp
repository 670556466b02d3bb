#include "grammar/grid_rules.h"

#include "grammar/asymmetric_spans.h"
#include "grammar/grid_end_units.h"
#include "grammar/sliding_units.h"
#include "grammar/whole_parts.h"
#include "geometry/slab_cut.h"
#include "symmetry/symmetric_region.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>

namespace dg {
namespace {

// Distance of a unit direction from the span of others above which it counts as independent
// (about 1 degree).
constexpr double kIndependentDirection = 0.02;

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
// order of the rest of the ranking) when the best of them has any.
constexpr std::size_t kLongestChainsCounted = 16;
// When the model leaves room for another unit beyond the best chain's, further chains with up to
// kShorterChainLevels fewer units between planes (at least one) are counted too, in ranking order,
// one per stretch of phases and kShorterChainsCounted in all: a phase whose planes cross thin
// dividers fits fewer units between planes than one through the cells, but may reach whole copies
// at both ends (a shelf's bottom and top rows, whose outer boards differ from its dividers).
// Moving the phase loses at most the plane at each end.
constexpr int kShorterChainLevels = 2;
constexpr std::size_t kShorterChainsCounted = 6;

// Whether the model spans `pitches` times the translation t (bounded by its bounding box): every
// plane crosses the model, so that many units need that much extent along t. A cheap rejection
// of large powers of short motions.
bool spans_pitches(const BoundingBox& bounds, const Vec3& t, int pitches) {
  return t.cwiseAbs().dot(bounds.size()) >= pitches * t.squaredNorm();
}

// The best chain of cut planes for one translation or screw motion: the longest run of planes,
// each crossing only r-symmetric cells (the last only images of them; the first also symmetric
// cells whose nearby asymmetry lies on one side of it) and none holding a face, whose slabs are
// symmetric, and (meshes) whose unit is no extrusion that only slides along itself. With a
// positive `copy_tolerance` (model units; meshes only) the copies of the unit beyond the first
// and last plane join the count (grammar/grid_end_units.h). A screw moves every plane across its
// axis by its slide along the axis, so its planes are those perpendicular to the axis, `slide`
// apart.
std::optional<GridDirection> grid_direction(const PreparedModel& prepared, const DetectedSymmetry& symmetry,
                                            std::size_t symmetry_index, int min_repeats, double max_slab_asymmetry,
                                            double copy_tolerance, const std::vector<std::pair<double, double>>& taken = {}) {
  const VoxelSurface& surface = prepared.surface;
  const ScrewParameters screw = screw_parameters(symmetry.transform);
  const Vec3 t = symmetry.kind == "translation" ? symmetry.transform.translation : screw.slide * screw.axis;
  const double pitch = t.norm();
  if (pitch <= 0.0) return std::nullopt;
  const Vec3 d = t / pitch;
  if (!spans_pitches(prepared.cleaning.bounds, t, min_repeats)) return std::nullopt;
  const double half = 0.5 * surface.eps() * (std::abs(d.x()) + std::abs(d.y()) + std::abs(d.z()));

  std::vector<char> in_r(surface.cell_count(), 0), in_xi(surface.cell_count(), 0);
  for (std::uint32_t c : symmetry.region.r_symmetric_cells) in_r[c] = 1;
  for (std::uint32_t c : symmetry.region.symmetric_cells) in_xi[c] = 1;
  Blocked forward, first_plane;
  SlabCells slab_cells;
  for (std::uint32_t c = 0; c < surface.cell_count(); ++c) {
    const double s = d.dot(surface.centre(c));
    if (!in_r[c]) forward.add(s - half, s + half);
    if (!in_xi[c]) first_plane.add(s - half, s + half);
    slab_cells.add(s, in_xi[c] != 0);
  }
  // Runs found before along this motion keep their planes and half a pitch around them.
  auto block_taken = [&](Blocked& blocked) {
    for (const auto& [lo, hi] : taken) blocked.add(lo - 0.5 * pitch, hi + 0.5 * pitch);
  };
  block_taken(forward);
  block_taken(first_plane);
  forward.finish();
  slab_cells.finish();

  // Candidate offsets of the first plane, taken modulo the pitch: a fine sampling of one period
  // plus every vertex coordinate of a mesh (cuts through existing seams need no new vertices; a
  // point cloud has no seams, only its extent counts).
  const bool points = prepared.model.is_point_cloud();
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  std::map<double, int> vertex_offsets;
  for (const Vec3& p : points ? prepared.model.cloud.positions : prepared.model.mesh.positions) {
    const double s = d.dot(p);
    if (!points) ++vertex_offsets[s];
    lowest = std::min(lowest, s);
    highest = std::max(highest, s);
  }
  std::map<double, int> phases;  // phase in [0, pitch) (up to rounding) -> vertices on a plane there
  const double step = std::min(surface.eps() / 4.0, pitch / 64.0);
  for (double phase = 0.0; phase < pitch; phase += step) phases.emplace(phase, 0);
  // Vertices whose phases differ by rounding alone (the seams of a turned model) share one: a
  // plane there passes through all of them, within the cuts' snapping distance.
  const double same_phase = 1e-7 * surface.eps();
  std::vector<std::pair<double, int>> at_vertices;
  for (const auto& [s, n] : vertex_offsets) {
    const double phase = std::fmod(s - lowest, pitch);
    at_vertices.emplace_back(phase > pitch - same_phase ? phase - pitch : phase, n);
  }
  std::sort(at_vertices.begin(), at_vertices.end());
  for (std::size_t i = 0; i < at_vertices.size();) {
    std::size_t end = i + 1;
    while (end < at_vertices.size() && at_vertices[end].first - at_vertices[end - 1].first <= same_phase) ++end;
    double sum = 0.0;
    int vertices = 0;
    for (std::size_t j = i; j < end; ++j) sum += at_vertices[j].first, vertices += at_vertices[j].second;
    phases[sum / static_cast<double>(end - i)] += vertices;
    i = end;
  }
  // Stretches of phases between those of vertices: index of the first vertex phase at or above
  // `phase`, doubled, plus one when the phase is a vertex phase.
  std::vector<double> vertex_phases;
  for (const auto& [phase, n] : phases)
    if (n > 0) vertex_phases.push_back(phase);
  auto phase_stretch = [&](double phase) {
    const auto at = std::lower_bound(vertex_phases.begin(), vertex_phases.end(), phase);
    return 2 * (at - vertex_phases.begin()) + (at != vertex_phases.end() && *at == phase ? 1 : 0);
  };
  // Every slab between planes `first` + k pitch, k < `slabs`, maps onto the next: (almost) no
  // asymmetric cell strictly inside.
  auto slabs_repeat = [&](double first, int slabs) {
    for (int k = 0; k < slabs; ++k) {
      const auto [asymmetric_cells, cells] = slab_cells.count(first + k * pitch + half, first + (k + 1) * pitch - half);
      if (static_cast<double>(asymmetric_cells) > max_slab_asymmetry * static_cast<double>(cells)) return false;
    }
    return true;
  };

  // Planes that hold a whole face: a cut there would leave the face on either side by rounding.
  std::vector<double> face_planes;
  const TriangleMesh& mesh = prepared.model.mesh;
  const double in_plane = 1e-6 * surface.eps();
  for (const Triangle& tri : mesh.triangles) {
    const double a = d.dot(mesh.positions[tri[0]]), b = d.dot(mesh.positions[tri[1]]), c = d.dot(mesh.positions[tri[2]]);
    if (std::max({a, b, c}) - std::min({a, b, c}) <= in_plane) face_planes.push_back(a);
  }
  std::sort(face_planes.begin(), face_planes.end());
  auto holds_a_face = [&](double plane) {
    const auto it = std::lower_bound(face_planes.begin(), face_planes.end(), plane - in_plane);
    return it != face_planes.end() && *it <= plane + in_plane;
  };

  // Surface cells crossed by the planes `first` + k pitch, k = 0 .. `count` (the seams' size),
  // or nothing when one of them holds a face.
  auto seam_cells = [&](double first, int count) -> std::optional<std::size_t> {
    std::size_t crossed = 0;
    for (int k = 0; k <= count; ++k) {
      if (holds_a_face(first + k * pitch)) return std::nullopt;
      crossed += slab_cells.count(first + k * pitch - half, first + k * pitch + half).second;
    }
    return crossed;
  };

  // A translation's generator is kept exact (no rotation noise from the detector's fit).
  const RigidTransform motion = symmetry.kind == "translation" ? RigidTransform{Mat3::Identity(), t} : symmetry.transform;
  // The chain starting at `first` with `count` units, its first unit the repeated one.
  auto unsettled = [&](double first, int count) {
    return GridDirection{.motion = motion, .translation = t, .direction = d, .pitch = pitch, .cut = first, .count = count,
                         .symmetry = symmetry_index};
  };
  // That chain with its repeated unit chosen and (with a copy tolerance) the copies beyond its
  // planes counted.
  auto count_copies_beyond = [&](GridDirection& direction) {
    if (copy_tolerance > 0.0) count_end_units(direction, mesh, copy_tolerance, prepared.material_classes);
  };
  auto settled = [&](double first, int count) {
    GridDirection direction = unsettled(first, count);
    choose_repeated_unit(direction, slab_cells, half, mesh);
    count_copies_beyond(direction);
    return direction;
  };
  struct Chain {
    double first = 0.0;
    double phase = 0.0;  // of its planes, in [0, pitch) from the model's lowest point
    int count = 0;
    double clearance = -1.0;
    std::size_t crossed = 0;
    int vertices = 0;
  };
  // A chain of more than `more_than` units that are copies side by side, though no chain of
  // them lies between planes in the r-symmetric area: the area between copies can be eroded by r
  // where one copy's outer boards lie close to the next copy's asymmetric end (a shelf of two
  // columns: its middle divider is thinner than 2r, and the second column maps beyond the model),
  // or be broken up where thin parts cross the voxels obliquely (a turned shelf's dividers). Seeds
  // are runs of slabs whose cells map onto the next slab's (slabs_repeat) at planes that hold no
  // face; each seed's first slab becomes the unit and its copies are verified on the mesh and
  // counted as in count_end_units. Seeds are ranked by more slabs, then more vertices on the
  // planes (cuts through existing seams leave copies cut alike), then smaller seams; one per
  // stretch of phases whose unit does not only slide along itself is verified, up to
  // kShorterChainsCounted of them, and the most units wins.
  auto copied_chain = [&](int more_than) -> std::optional<GridDirection> {
    if (points || copy_tolerance <= 0.0) return std::nullopt;
    auto maps_onto_next = [&](double first) {  // a slab with surface that maps onto the next
      return slab_cells.count(first + half, first + pitch - half).second > 0 && slabs_repeat(first, 1);
    };
    std::vector<Chain> seeds;
    for (const auto& [phase, vertices] : phases)
      for (double first = lowest + phase - pitch; first <= highest; first += pitch) {
        if (!maps_onto_next(first) || maps_onto_next(first - pitch)) continue;
        int count = 2;  // slabs: those that map onto the next, and the last image
        while (maps_onto_next(first + (count - 1) * pitch)) ++count;
        if (count < min_repeats || count <= more_than) continue;
        if (const std::optional<std::size_t> crossed = seam_cells(first, count))
          seeds.push_back(Chain{first, phase, count, 0.0, *crossed, vertices});
      }
    std::stable_sort(seeds.begin(), seeds.end(), [](const Chain& a, const Chain& b) {
      if (a.count != b.count) return a.count > b.count;
      return a.vertices != b.vertices ? a.vertices > b.vertices : a.crossed < b.crossed;
    });
    std::set<std::ptrdiff_t> stretches;
    std::size_t verified = 0;
    std::optional<GridDirection> best;
    for (const Chain& seed : seeds) {
      // A seed's slabs bound its copies: none of the rest can reach further.
      if (verified == kShorterChainsCounted || (best && best->count >= seed.count)) break;
      // The unit stays the seed's first slab however far the copies reach, so an extrusion is
      // told before the costly check.
      if (!stretches.insert(phase_stretch(seed.phase)).second || unit_only_slides(mesh, unsettled(seed.first, 1))) continue;
      ++verified;
      // The copies are found beyond the seed's unit; those that also repeat cell for cell become
      // repeated units instead of being kept once.
      GridDirection direction = unsettled(seed.first, 1);
      count_copies_beyond(direction);
      choose_repeated_unit(direction, slab_cells, half, mesh);
      if (direction.count >= min_repeats && direction.count > more_than && (!best || direction.count > best->count))
        best = std::move(direction);
    }
    return best;
  };

  // A quick test whether any run of min_repeats units may exist, before the costly parts (the
  // image of the r-symmetric area, the asymmetry near the first plane): their tests only take
  // planes away, so without such a run here there is none below.
  first_plane.finish();
  bool may_repeat = false;
  for (auto phase = phases.begin(); phase != phases.end() && !may_repeat; ++phase)
    for (double first = lowest + phase->first; first <= highest && !may_repeat; first += pitch) {
      if (first_plane.contains(first)) continue;
      int free = 1;
      while (free < min_repeats && first + free * pitch <= highest && !forward.contains(first + free * pitch)) ++free;
      may_repeat = free == min_repeats && slabs_repeat(first, min_repeats - 1);
    }
  // A further run along the motion is a chain between planes (copies side by side are sought
  // for the first run only).
  const bool further = !taken.empty();
  if (!may_repeat) return further ? std::nullopt : copied_chain(0);

  std::vector<char> in_image(surface.cell_count(), 0);
  const CellMatcher matcher(surface, nullptr);
  // A cell lies in the image when its preimage does lie in the r-symmetric region (pulled back,
  // so a rotation's rounding to voxels leaves no holes in the image).
  const RigidTransform inverse = symmetry.transform.inverse();
  for (std::uint32_t c = 0; c < surface.cell_count(); ++c) {
    const std::int64_t preimage = matcher.image_cell(c, inverse);
    if (preimage >= 0 && in_r[static_cast<std::size_t>(preimage)]) in_image[c] = 1;
  }
  // The first plane may also cross symmetric cells near asymmetric ones (damage such as a fin)
  // when all that asymmetry lies on one side of it: the r-neighbourhoods of the seams between
  // copied units then occur in the exemplar, at the first plane (asymmetry above it: the head's
  // top is a copy of the unit's top) or at the second (asymmetry below: the second unit's bottom
  // is a copy of the first's).
  const std::vector<PositionSpan> spans = asymmetric_spans(surface, in_xi, d, surface.r());
  Blocked backward;
  for (std::uint32_t c = 0; c < surface.cell_count(); ++c) {
    const double s = d.dot(surface.centre(c));
    if (!in_image[c]) backward.add(s - half, s + half);
    if (in_xi[c] && !in_r[c] && !spans[c].empty()) {
      const double lo = std::max(s - half, spans[c].lo - half), hi = std::min(s + half, spans[c].hi + half);
      if (lo <= hi) first_plane.add(lo, hi);
    }
  }
  block_taken(backward);
  backward.finish();
  first_plane.finish();

  // The best chain whose first unit lies outside every range in `sliding`. Ranking: more units
  // between planes; then, when the best by the rest counts copies beyond its planes or leaves room
  // for them (the phase decides whether whole copies remain at the ends), more units in all
  // (kLongestChainsCounted, kShorterChainLevels); then more clearance (beyond rounding); then the
  // smallest seams (fewest surface cells crossed by the planes); then planes through more existing
  // vertices.
  const double wanted_clearance = surface.r();
  auto best_chain = [&](const std::vector<std::pair<double, double>>& sliding) -> std::optional<GridDirection> {
    auto excluded = [&](double first) {
      return std::any_of(sliding.begin(), sliding.end(),
                         [&](const auto& range) { return first < range.second && first + pitch > range.first; });
    };
    std::vector<Chain> chains;  // every run of at least one unit (shorter ones may reach copies)
    for (const auto& [phase, vertices] : phases) {
      // Walk the planes lowest + phase + j * pitch across the model and find runs of allowed ones.
      for (double first = lowest + phase; first <= highest; first += pitch) {
        // Not a run start: blocked, or the run from the plane before includes this one.
        if (first_plane.contains(first) || excluded(first) ||
            (first - pitch >= lowest && !first_plane.contains(first - pitch) && !forward.contains(first) && !excluded(first - pitch)))
          continue;
        int count = 1;
        while (!forward.contains(first + count * pitch) && first + count * pitch <= highest) ++count;
        // The plane after the last unit must lie in the image of the r-symmetric area.
        while (count > 0 && backward.contains(first + count * pitch)) --count;
        // Every slab but the last maps onto the next.
        for (int k = 0; k + 1 < count; ++k)
          if (!slabs_repeat(first + k * pitch, 1)) {
            count = k + 1;
            break;
          }
        if (count < 1) continue;
        const std::optional<std::size_t> crossed = seam_cells(first, count);
        if (!crossed) continue;
        double clearance = wanted_clearance;
        clearance = std::min(clearance, first_plane.clearance(first));
        for (int k = 1; k < count; ++k) clearance = std::min(clearance, forward.clearance(first + k * pitch));
        clearance = std::min(clearance, backward.clearance(first + count * pitch));
        chains.push_back(Chain{first, phase, count, clearance, *crossed, vertices});
      }
    }
    if (chains.empty()) return std::nullopt;
    std::stable_sort(chains.begin(), chains.end(), [](const Chain& a, const Chain& b) {
      if (a.count != b.count) return a.count > b.count;
      if (std::abs(a.clearance - b.clearance) > 1e-12) return a.clearance > b.clearance;
      return a.crossed != b.crossed ? a.crossed < b.crossed : a.vertices > b.vertices;
    });
    const int longest = chains[0].count;
    if (longest < min_repeats) return std::nullopt;
    GridDirection best = settled(chains[0].first, longest);
    if (copy_tolerance <= 0.0) return best;
    // Copies beyond the planes, or room for them: other phases may leave more units in all.
    const bool beyond = best.count > longest, room = (best.count + 1) * pitch <= highest - lowest;
    // With room, one chain per stretch between vertex phases is counted: its planes cross the
    // same edges as any other chain's there.
    std::set<std::ptrdiff_t> stretches{phase_stretch(chains[0].phase)};
    std::size_t longest_counted = 1, shorter_counted = 0;
    for (std::size_t i = 1; i < chains.size(); ++i) {
      const Chain& chain = chains[i];
      if (chain.count == longest && beyond) {
        if (longest_counted == kLongestChainsCounted) continue;
        ++longest_counted;
      } else {
        if (!room || chain.count < longest - kShorterChainLevels || shorter_counted == kShorterChainsCounted ||
            !stretches.insert(phase_stretch(chain.phase)).second)
          continue;
        ++shorter_counted;
      }
      GridDirection other = settled(chain.first, chain.count);
      if (other.count > best.count) best = std::move(other);
    }
    return best;
  };
  // An extrusion cut at the pitch (a corridor reaching out of a map) is no row of units: its
  // chain is left out and the next best taken, a few times at most.
  constexpr int kSlidingChainsTried = 4;
  std::vector<std::pair<double, double>> sliding;
  std::optional<GridDirection> best = best_chain(sliding);
  if (!best) return further ? std::nullopt : copied_chain(0);
  while (best && !points && unit_only_slides(mesh, *best)) {
    if (static_cast<int>(sliding.size()) + 1 >= kSlidingChainsTried) return std::nullopt;
    sliding.emplace_back(best->cut, best->cut + best->count * pitch);
    best = best_chain(sliding);
  }
  // Units counted beyond its planes may not reach into a run found before, and the runs next to
  // it must lie apart: what lies between is mostly a different part (a gate between two stretches
  // of fence), not more of the row that planes could not cross (brackets behind a radiator's fins).
  if (further && best) {
    const double lo = best->cut, hi = best->cut + best->count * pitch;
    double below = -std::numeric_limits<double>::infinity(), above = std::numeric_limits<double>::infinity();
    for (const auto& [a, b] : taken) {
      if (lo < b && hi > a) return std::nullopt;
      if (b <= lo) below = std::max(below, b);
      if (a >= hi) above = std::min(above, a);
    }
    auto mostly_different = [&](double from, double to) {
      const auto [asymmetric_cells, cells] = slab_cells.count(from, to);
      return 2 * asymmetric_cells > cells;
    };
    if ((std::isfinite(below) && !mostly_different(below, lo)) || (std::isfinite(above) && !mostly_different(hi, above)))
      return std::nullopt;
    return best;
  }
  // Room for another unit: copies side by side at another phase may reach further.
  if (best && (best->count + 1) * pitch <= highest - lowest)
    if (std::optional<GridDirection> copied = copied_chain(best->count)) best = std::move(copied);
  return best;
}

// Whether t leaves the span of the chosen directions by more than about 1 degree: detected
// generators carry noise (zdm2: (2, 0.002, -0.001) and (6, -0.001, 0.001) are one direction).
bool independent_of(const Vec3& t, const std::vector<GridDirection>& chosen) {
  if (chosen.empty()) return true;
  Eigen::Matrix<double, 3, Eigen::Dynamic> basis(3, static_cast<Eigen::Index>(chosen.size()));
  for (std::size_t i = 0; i < chosen.size(); ++i) basis.col(static_cast<Eigen::Index>(i)) = chosen[i].direction;
  const Vec3 unit = t.normalized();
  const Eigen::VectorXd coefficients = basis.colPivHouseholderQr().solve(unit);
  return (basis * coefficients - unit).norm() > kIndependentDirection;
}

// A family's members, generator first, then by power: a generator can be a motion that maps only
// outlines onto outlines (half a window pitch on a painted wall), while its square repeats whole
// units. Larger powers of a working generator would give fewer units.
std::vector<std::size_t> members_by_power(const SymmetryFamily& family) {
  std::vector<std::size_t> by_power(family.members.size());
  std::iota(by_power.begin(), by_power.end(), std::size_t{0});
  std::stable_sort(by_power.begin(), by_power.end(), [&](std::size_t a, std::size_t b) {
    return std::abs(family.powers[a]) < std::abs(family.powers[b]);
  });
  return by_power;
}

// Extent of a set of triangles along a direction and in space.
struct Extent {
  BoundingBox box;
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  double weighted_centre = 0.0, area = 0.0;  // area-weighted position of the triangle centres
};

// Places the groups of parts kept whole along `direction` (found on the rest of the model): a
// group whose centre lies before the middle of the units goes with the head, else with the tail.
// Fails when no unit holds a part (not kept whole) that lies inside it, or a group reaches across
// all units. Returns the fewest units at which the groups moved with the tail stay more than r from
// those placed with the head and out of the head's slab, and the head's groups out of the tail's.
std::optional<int> place_whole_parts(GridDirection& direction, const TriangleMesh& mesh, const ModelParts& model,
                                     const WholeParts& whole, double r) {
  const Vec3& d = direction.direction;
  const double first = direction.cut, last = direction.cut + direction.count * direction.pitch;
  std::map<std::uint32_t, Extent> groups;
  std::vector<Extent> parts(whole.kept.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::uint32_t p = model.part[t];
    Extent& e = whole.kept[p] ? groups[whole.group[p]] : parts[p];
    const auto corners = mesh.corners(t);
    for (const Vec3& x : corners) {
      e.box.add(x);
      e.lo = std::min(e.lo, d.dot(x));
      e.hi = std::max(e.hi, d.dot(x));
    }
    const double area = 0.5 * mesh.area_vector(t).norm();
    e.weighted_centre += area * d.dot((corners[0] + corners[1] + corners[2]) / 3.0);
    e.area += area;
  }
  const double margin = 1e-6 * direction.pitch;
  const bool unit_holds_a_part = std::any_of(parts.begin(), parts.end(), [&](const Extent& e) {
    if (e.area <= 0.0 || e.lo <= first + margin || e.hi >= last - margin) return false;
    return std::floor((e.lo - first) / direction.pitch) == std::floor((e.hi - first) / direction.pitch);
  });
  if (!unit_holds_a_part) return std::nullopt;
  const double middle = 0.5 * (first + last);
  std::vector<const Extent*> head, tail;
  std::map<std::uint32_t, bool> in_head;
  for (const auto& [group, e] : groups) {
    in_head[group] = e.weighted_centre < middle * e.area;
    (in_head[group] ? head : tail).push_back(&e);
  }
  int fewest = 0;
  for (const Extent* e : head) {
    if (e->hi + r > last) return std::nullopt;
    fewest = std::max(fewest, static_cast<int>(std::ceil((e->hi + r - first) / direction.pitch)));
  }
  for (const Extent* e : tail) {
    if (e->lo - r < first) return std::nullopt;
    fewest = std::max(fewest, direction.count - static_cast<int>(std::floor((e->lo - r - first) / direction.pitch)));
  }
  // Between those bounds a tail group moved back may still come near a head group.
  for (int units = direction.count - 1; units >= fewest; --units) {
    const Vec3 back = -(direction.count - units) * direction.translation;
    const bool meets = std::any_of(tail.begin(), tail.end(), [&](const Extent* t) {
      return std::any_of(head.begin(), head.end(), [&](const Extent* h) { return boxes_within(t->box.shifted(back), h->box, 2.0 * r); });
    });
    if (meets) {
      fewest = units + 1;
      break;
    }
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::uint32_t p = model.part[t];
    if (whole.kept[p]) (in_head[whole.group[p]] ? direction.whole_in_head : direction.whole_in_tail).push_back(static_cast<std::uint32_t>(t));
  }
  return fewest;
}

// Runs of a direction sought beyond its first, apart from each other.
constexpr std::size_t kFurtherRuns = 3;

// Members of a family tried for a row of parts: the generator and its square (each builds the
// voxel surface of the rest of the model and tests its every cell).
constexpr std::size_t kRowMembersTried = 2;

// A direction whose planes cut the model but for parts kept whole, and the fewest units it allows.
struct RowOfParts {
  GridDirection direction;
  int fewest_units = 0;
};

// The translation with the most units whose planes cut the model but for parts kept whole (for
// each family, the first member by power that gives one).
std::optional<RowOfParts> row_of_parts(const PreparedModel& prepared, const SymmetryResult& symmetries,
                                       const GridOptions& options) {
  const ModelParts parts = model_parts(prepared.model.mesh);
  // Families are independent: tried in parallel, compared in family order.
  std::vector<std::optional<RowOfParts>> rows(symmetries.families.size());
  tbb::parallel_for(std::size_t(0), rows.size(), [&](std::size_t f) {
    const SymmetryFamily& family = symmetries.families[f];
    if (family.kind != "translation" || family.count == 0) return;  // count 0: it only slides walls and rails
    const std::vector<std::size_t> by_power = members_by_power(family);
    for (std::size_t i = 0; i < std::min(by_power.size(), kRowMembersTried); ++i) {
      const std::size_t member = family.members[by_power[i]];
      const DetectedSymmetry& symmetry = symmetries.symmetries[member];
      if (!spans_pitches(prepared.cleaning.bounds, symmetry.transform.translation, options.min_repeats)) continue;
      const WholeParts whole = whole_parts(prepared, parts, symmetry, symmetries.region);
      if (whole.empty()) continue;
      std::optional<GridDirection> direction =
          grid_direction(whole.rest, whole.motion, member, options.min_repeats, options.max_slab_asymmetry,
                         0.0);  // parts are placed for the units between planes: no units beyond them
      if (!direction) continue;
      const std::optional<int> fewest = place_whole_parts(*direction, prepared.model.mesh, parts, whole, prepared.surface.r());
      if (!fewest) continue;
      rows[f] = RowOfParts{std::move(*direction), *fewest};
      return;
    }
  });
  std::optional<RowOfParts> best;
  for (std::optional<RowOfParts>& row : rows)
    if (row && (!best || row->direction.count > best->direction.count)) best = std::move(row);
  return best;
}

}  // namespace

std::vector<GridRule> find_grids(const PreparedModel& prepared, const SymmetryResult& symmetries,
                                 const GridOptions& options, const ProgressCallback& progress) {
  std::vector<GridRule> grids;
  std::vector<GridDirection> translations, screws;
  // Units near the model's ends that no plane may reach (r-erosion) count when they are copies
  // within the cells' offset tolerance the symmetries were found with (a point cloud's sampling
  // cannot tell a copy from a slab shifted by less than eps).
  const double copy_tolerance =
      prepared.model.is_point_cloud() ? 0.0 : symmetries.region.offset_tolerance_eps * prepared.surface.eps();
  std::vector<std::size_t> repeated_generators;  // translations that repeat but gave no direction
  // Families are independent: examined in parallel and joined in family order.
  const std::size_t family_count = symmetries.families.size();
  std::vector<std::optional<GridDirection>> found(family_count);
  parallel_for_reporting(family_count, progress, "grid rules", [&](std::size_t f) {
    const SymmetryFamily& family = symmetries.families[f];
    if (family.kind != "translation" && family.kind != "screw") return;
    for (std::size_t m : members_by_power(family)) {
      found[f] = grid_direction(prepared, symmetries.symmetries[family.members[m]], family.members[m], options.min_repeats,
                                options.max_slab_asymmetry, copy_tolerance);
      if (found[f]) return;
    }
  });
  for (std::size_t f = 0; f < family_count; ++f) {
    const SymmetryFamily& family = symmetries.families[f];
    if (found[f])
      (family.kind == "translation" ? translations : screws).push_back(*found[f]);
    else if (family.kind == "translation" && static_cast<int>(family.count) >= options.min_repeats)
      repeated_generators.push_back(family.members[members_by_power(family).front()]);
  }
  // Most units first; then combine independent translations into one grid.
  // Ties keep a readable order: directions closest to x, then y, then z.
  auto axis_of = [](const GridDirection& d) {
    Eigen::Index axis = 0;
    d.direction.cwiseAbs().maxCoeff(&axis);
    return axis;
  };
  auto more_units = [&](const GridDirection& a, const GridDirection& b) {
    return a.count != b.count ? a.count > b.count : axis_of(a) < axis_of(b);
  };
  // A translation that is a power of a screw with more units (a full turn of a spiral stair that
  // climbs more than one) gives way to the screw: its units hold several of the screw's.
  const Vec3 middle = 0.5 * (prepared.cleaning.bounds.min + prepared.cleaning.bounds.max);
  std::erase_if(translations, [&](const GridDirection& translation) {
    return std::any_of(screws.begin(), screws.end(), [&](const GridDirection& screw) {
      const int turn = static_cast<int>(std::lround(translation.pitch / screw.pitch));
      return screw.count > translation.count && turn >= 2 &&
             same_motion(power(screw.motion, turn), translation.motion, middle, prepared.surface.eps());
    });
  });
  std::stable_sort(translations.begin(), translations.end(), more_units);
  std::stable_sort(screws.begin(), screws.end(), more_units);
  auto next_grid = [&]() {
    GridRule grid;
    grid.name = "grid" + std::to_string(grids.size() + 1);
    grid.max_count = options.max_count;
    return grid;
  };
  GridRule grid = next_grid();
  for (const GridDirection& direction : translations)
    if (grid.directions.size() < 3 && independent_of(direction.translation, grid.directions)) grid.directions.push_back(direction);
  // A translation the model repeats (as many of its powers are symmetries) whose planes fit only
  // one unit across the whole model, because of parts such as rooftop structures between the bays
  // of a facade, joins a grid that exists as a direction with one unit: resizing adds bays where
  // the planes are free.
  for (std::size_t s : repeated_generators) {
    if (grid.directions.empty() || grid.directions.size() >= 3 ||
        !independent_of(symmetries.symmetries[s].transform.translation, grid.directions))
      continue;
    if (auto direction = grid_direction(prepared, symmetries.symmetries[s], s, 1, options.max_slab_asymmetry, copy_tolerance))
      grid.directions.push_back(*direction);
  }
  // No translation cuts across the whole model: a row of parts may, keeping other parts whole
  // (a mesh's connected components; a point cloud has none).
  if (grid.directions.empty() && !prepared.model.is_point_cloud())
    if (std::optional<RowOfParts> row = row_of_parts(prepared, symmetries, options)) {
      grid.min_count = row->fewest_units;
      grid.directions.push_back(std::move(row->direction));
    }
  if (!grid.directions.empty()) grids.push_back(std::move(grid));
  // A screw commutes only with motions along its own axis, so each screw is a 1-grid of its own;
  // screws along the same axis (powers of one another, one screw found twice, or an axis the
  // translation grid already cuts across) give no further grid.
  std::vector<GridDirection> chosen_screws = grids.empty() ? std::vector<GridDirection>{} : grids[0].directions;
  for (const GridDirection& direction : screws) {
    if (!independent_of(direction.translation, chosen_screws)) continue;
    chosen_screws.push_back(direction);
    GridRule screw_grid = next_grid();
    screw_grid.directions.push_back(direction);
    grids.push_back(std::move(screw_grid));
  }
  // Further runs of grid1's directions, apart from the first (fences on both sides of a gate):
  // each is a 1-grid of its own, its planes clear of the runs found before.
  if (!grids.empty() && !prepared.model.is_point_cloud()) {
    const std::vector<GridDirection> first_runs = grids[0].directions;
    for (const GridDirection& run : first_runs) {
      if (run.count < options.min_repeats || !run.whole_in_head.empty() || !run.whole_in_tail.empty()) continue;
      std::vector<std::pair<double, double>> taken{{run.cut, run.cut + run.count * run.pitch}};
      while (taken.size() <= kFurtherRuns) {
        std::optional<GridDirection> further =
            grid_direction(prepared, symmetries.symmetries[run.symmetry], run.symmetry, options.min_repeats,
                           options.max_slab_asymmetry, copy_tolerance, taken);
        if (!further) break;
        taken.emplace_back(further->cut, further->cut + further->count * further->pitch);
        GridRule further_grid = next_grid();
        further_grid.directions.push_back(std::move(*further));
        grids.push_back(std::move(further_grid));
      }
    }
  }
  report_progress(progress, "grid rules", 1.0);
  return grids;
}

}  // namespace dg
