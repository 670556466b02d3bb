#pragma once
// One direction of a grid: the chain of cut planes a translation or screw motion gives a model
// (the planes, their pitch, how many units lie between them and beyond them). find_grids
// (grammar/grid_rules.h) combines directions into grids.

#include "geometry/prepared_model.h"
#include "geometry/types.h"
#include "grammar/grid_rules.h"
#include "symmetry/symmetry_detection.h"

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace dg {

/// What the search for one direction looks for.
struct DirectionSearch {
  int min_repeats = 2;               ///< fewest units between planes
  double max_slab_asymmetry = 0.03;  ///< GridOptions::max_slab_asymmetry
  /// Model units, meshes only: with a positive value the copies of the unit beyond the first and
  /// last plane join the count (grammar/grid_end_units.h).
  double copy_tolerance = 0.0;
  /// Runs found before along this motion, as the positions of their first and last planes along
  /// it: the search is for a further run, whose planes keep half a pitch clear of them and which
  /// lies apart from its neighbours by mostly asymmetric geometry.
  std::vector<std::pair<double, double>> taken{};
};

/// Whether the model spans `pitches` times the translation t (bounded by its bounding box): every
/// plane crosses the model, so that many units need that much extent along t. A cheap rejection
/// of large powers of short motions.
bool spans_pitches(const BoundingBox& bounds, const Vec3& t, int pitches);

/// The best chain of cut planes for one translation or screw motion (`symmetry`, at
/// `symmetry_index` in the symmetry result): the longest run of planes, each crossing only
/// r-symmetric cells (the last only images of them; the first also symmetric cells whose nearby
/// asymmetry lies on one side of it) and none holding a face, whose slabs are symmetric, and
/// (meshes) whose unit is no extrusion that only slides along itself; with a copy tolerance, the
/// copies of the unit beyond the first and last plane counted too. A screw moves every plane
/// across its axis by its slide along the axis, so its planes are those perpendicular to the
/// axis, `slide` apart. Nothing when no run of search.min_repeats units exists.
std::optional<GridDirection> grid_direction(const PreparedModel& prepared, const DetectedSymmetry& symmetry,
                                            std::size_t symmetry_index, const DirectionSearch& search);

}  // namespace dg
