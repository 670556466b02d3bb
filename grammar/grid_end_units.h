#pragma once
// Units of a grid direction that lie beyond its cut planes: copies of the repeated unit near the
// model's ends, where the symmetric area is eroded by r, so no cut plane may cross it.

#include "geometry/flat_regions.h"
#include "grammar/grid_rules.h"

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace dg {

/// Relative difference of surface area below which two slabs of a grid count as equally large
/// (a hidden second layer of faces, invisible to the voxel cells, tells them apart).
inline constexpr double kSameSlabArea = 1e-4;

/// A mesh measured along one direction for count_end_units: its extent and its connected parts.
/// A motion's search counts end units for many chains along one direction, so it measures once.
struct MeshAlong {
  double lowest = 0.0, highest = 0.0;  ///< extent along the direction, model units
  /// Connected components: their triangles, area-weighted centroids, areas and extents along the
  /// direction; and (centroid position along the direction, part), ascending.
  std::vector<std::vector<std::size_t>> part_triangles;
  std::vector<Vec3> part_centroids;
  std::vector<double> part_areas;
  std::vector<std::pair<double, double>> part_spans;
  std::vector<std::pair<double, std::size_t>> parts_by_position;
  /// Flat regions that do not lie across the direction (see flat_regions; their materials
  /// replaced by their classes, 0 when materials are not matched), their spans along it, and
  /// (lower end of the span, region), ascending.
  std::vector<FlatRegion> flat_regions;
  std::vector<std::pair<double, double>> region_spans;
  std::vector<std::pair<double, std::size_t>> regions_by_start;
};

/// Measures `mesh` along the unit vector `direction` for count_end_units; `material_classes` as
/// count_end_units takes them.
MeshAlong measure_along(const TriangleMesh& mesh, const Vec3& direction, std::span<const std::uint32_t> material_classes = {});

/// Extends `direction` (found on `mesh`, a triangle mesh) by the copies of the unit that lie before
/// its first plane and after its last: while the slab one pitch before the first plane, moved by
/// the direction's motion, is the same surface as the slab after it within `tolerance` (model
/// units; geometry/same_surface.h) and has the same area (kSameSlabArea, so a hidden second layer
/// of faces counts), the first plane moves back one pitch and the slab joins the count as a unit
/// kept in the head; likewise after the last plane for the tail. A slab that reaches the model's
/// first or last plane across the direction is also compared without the faces in that plane (end
/// caps, such as a plate's end under a row of keys), and a slab that holds, in its outer plane, the
/// face of a part beginning there (the side of a bookshelf against its last book) without the faces
/// in that plane. Then, when the part of the model before the first plane, moved by the motion, is
/// the unit's part just after its own first plane and the part after the last plane, moved back,
/// the unit's part before its last plane, the two one pitch long together (faces in the planes
/// where they meet left out: a row of touching lockers cut between their handles), they count as
/// one more unit kept in the head (a split unit: at the smallest count the head and tail pieces
/// join into it). Without a split unit, and when the unit repeats as a whole slab at least once
/// (two units counted so far), the count then goes on outward by units whose slabs are no copies
/// but whose own parts are: every connected component lying wholly in the repeated unit's slab (at
/// least 7 % of its surface) has a copy, the same surface within `tolerance`, moved by the
/// motion's power to the slab (a colonnade's end columns, which stand under the ends of its beam
/// and steps); a unit with no such part (every part runs on across its planes) goes on by units
/// whose own flat faces are copies: every flat region lying wholly in its slab and not across the
/// direction (at least 7 % of its surface; a straight stair's top step, whose tread is a copy
/// though the stair's end face lies in its slab). Resizing to the new count still gives the
/// exemplar (head and tail pieces are unchanged), and each further unit adds one copy of the
/// repeated unit. Materials are compared by
/// `material_classes` (the class of each material index, as the symmetries matched them: random
/// tints grouped as one); empty (materials not matched) compares the shapes alone. `measured`:
/// measure_along(mesh, direction.direction, material_classes), or null to measure here. Returns
/// the units added.
int count_end_units(GridDirection& direction, const TriangleMesh& mesh, double tolerance,
                    std::span<const std::uint32_t> material_classes, const MeshAlong* measured = nullptr);

}  // namespace dg
