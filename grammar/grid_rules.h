#pragma once
// Grid rules (paper 001 §3.4.3) for translational repetitions and screw motions: a k-grid cuts
// the model by k families of parallel planes into corner, border and interior pieces; resizing
// to N units places the head piece of a direction once, the repeated unit N - (units the head
// and tail keep) times and the tail piece once.
// A screw (spiral stairs) cuts along planes perpendicular to its axis, its slide apart, and
// forms a 1-grid of its own (it commutes only with motions along its axis).
//
// A direction d with generator translation t (pitch p = |t|) has cut planes d . x = cut + j p,
// j = 0 .. count. Each plane crosses only r-symmetric area (the first may also cross symmetric
// area whose nearby asymmetry lies all on one side of it), so every seam of a resized model
// looks locally like a seam of the exemplar (r-similarity), and the `count` slabs between the
// planes are copies of each other (symmetric under t up to a little damage, see
// GridOptions::max_slab_asymmetry), so count copies of the first slab reproduce the exemplar.

#include "geometry/mesh.h"
#include "geometry/rigid_transform.h"
#include "geometry/prepared_model.h"
#include "geometry/progress.h"
#include "symmetry/symmetry_detection.h"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace dg {

/// One direction of a grid.
struct GridDirection {
  RigidTransform motion;            ///< generator: unit k + 1 = motion(unit k)
  Vec3 translation = Vec3::Zero();  ///< its translation t, or a screw's slide along its axis, model units
  Vec3 direction = Vec3::UnitX();   ///< t / |t|
  double pitch = 0.0;               ///< |t|
  double cut = 0.0;                 ///< offset of the first cut plane along direction
  int count = 0;                    ///< repeated units in the exemplar
  /// Units of the exemplar kept in the head piece (before the repeated one) and in the tail piece
  /// (after the last copy) because they differ a little from their neighbours (damage such as a
  /// fin, an end stake) or lie within r of the model's ends, where no plane may cut
  /// (grammar/grid_end_units.h): they are placed once, never copied. The repeated unit is slab
  /// head_units + 1; a resize places it count - head_units - tail_units times.
  int head_units = 0;
  int tail_units = 0;
  /// One of the head units is split between the ends: the part before the first plane is its end
  /// and the part after the last plane its beginning (grammar/grid_end_units.h).
  bool split_unit = false;
  std::size_t symmetry = 0;         ///< index of the generator in SymmetryResult::symmetries
  /// Separate parts kept whole instead of cut (grammar/whole_parts.h), as triangles of the
  /// cleaned model: placed once with the head, or moved with the tail. Empty when the planes
  /// cut the whole model; only analysis fills them (the grid's pieces carry the parts).
  std::vector<std::uint32_t> whole_in_head{}, whole_in_tail{};
};

/// Units of the exemplar a direction's head and tail keep: its count with no copy of the unit.
inline int min_units(const GridDirection& direction) { return direction.head_units + direction.tail_units; }

/// A k-grid: its directions (counts[i] belongs to directions[i]) and the allowed count range.
struct GridRule {
  std::string name;
  std::vector<GridDirection> directions;
  int min_count = 0;     ///< every direction accepts counts in [min_count, max_count]
  int max_count = 1000;
  /// How closely the seams of its pieces meet where a resize joins them, model units
  /// (grid_seam_misfit, grammar/grid_seams.h; measured once the pieces are cut).
  double seam_misfit = 0.0;
};

struct GridOptions {
  /// A grid needs a direction with at least this many units. Further translations may join it
  /// with a single unit when they repeat in the model (its powers 1 .. this many are symmetries
  /// that pin a unit, SymmetryFamily::count; a motion that only slides flat walls along
  /// themselves does not repeat) but their planes fit only one unit across it.
  int min_repeats = 2;
  int max_count = 1000; ///< largest count offered to resize
  /// A slab counts as a copy of the next when at most this fraction of its surface cells lies
  /// outside the symmetric region: absorbs pipeline damage (back-to-back duplicate faces, fins,
  /// slivers) while a different part (a door where the next slab has a window) stays larger.
  double max_slab_asymmetry = 0.03;
};

/// The exemplar's count in each direction of `grid` (resizing to them reproduces it).
inline std::vector<int> exemplar_counts(const GridRule& grid) {
  std::vector<int> counts;
  for (const GridDirection& d : grid.directions) counts.push_back(d.count);
  return counts;
}

/// Smallest count direction i of `grid` accepts: the grid's min_count, and at least the units
/// its head and tail keep.
inline int lowest_count(const GridRule& grid, std::size_t i) {
  return std::max(grid.min_count, min_units(grid.directions[i]));
}

/// How a grid groups the units of another along one direction (find_grids' grid of bays beside
/// grid1's window columns): the direction and how many of the other's units make one.
struct GroupedUnits {
  std::size_t direction = 0;
  int factor = 0;
};

/// Whether `grid` groups the units of `other`: both have the same directions but one, whose
/// translation is a whole multiple (2 or more) of `other`'s there (within 1e-6 of its pitch).
std::optional<GroupedUnits> grouped_units(const GridRule& grid, const GridRule& other);

/// Whether grids spanning `spanned` repeats of a translation family's generator cover fewer than
/// half of its `repeats` (SymmetryFamily::count): a short run of it.
inline bool short_run(double spanned, std::size_t repeats) { return 2.0 * spanned < static_cast<double>(repeats); }

/// Finds grids from the detected symmetry families. A family's generator gives its direction, or
/// when it has none, the next power that does; a translation's direction whose units span a
/// short_run of the family's repeats gives way to the first larger power's that does not (the
/// spans of a bridge rather than the posts between two piers). Independent translations are
/// combined into one k-grid, "grid1" (their cut planes are each valid over the whole model, and
/// translations commute); directions that are sums of chosen ones are dropped. The direction with the most
/// units needs GridOptions::min_repeats of them; the others may have one (see min_repeats). Each screw axis gives a
/// further 1-grid. Rotations (no slide) give none. When no translation gives a direction, the
/// translation with the most units whose planes cut all but some separate parts kept whole
/// (grammar/whole_parts.h) gives a 1-grid, if one of its units holds a whole part that no plane
/// cuts (a row of parts, not only walls and rails sliding along themselves). A mesh's chain of
/// planes whose unit only slides along itself (grammar/sliding_units.h) gives way to the next best
/// chain, and copies of the unit beyond the first and last plane join the count
/// (grammar/grid_end_units.h); a mesh's slabs that are copies of the next side by side (checked
/// on the mesh, planes anywhere but on a face) give the direction when no chain of min_repeats
/// units lies in the r-symmetric area or when they reach more units. A further run of a
/// direction of grid1 with min_repeats units (planes at least half a pitch clear of the runs
/// before, what lies between it and its neighbouring runs mostly outside the symmetric region,
/// such as a gate between two stretches of fence) gives a 1-grid of its own, after the screws'
/// grids, up to three per direction; a point cloud gets none. A direction of grid1 that keeps
/// most of its units once, because the model changes every few units (a pilaster after every
/// third window column), gives a last grid with grid1's other directions and, in its place, the
/// direction of a larger power of its generator whose units repeat (bays of three columns; of
/// the first four larger powers that repeat over at least twice as many of the generator's
/// pitches, the one that repeats over the most); a point cloud gets none. Families are examined
/// in parallel; the result does not depend on the thread count. `progress` hears stage "grid
/// rules" with the fraction of repetition families examined (after each parallel batch), then 1.
std::vector<GridRule> find_grids(const PreparedModel& prepared, const SymmetryResult& symmetries,
                                 const GridOptions& options = {}, const ProgressCallback& progress = {});

}  // namespace dg
