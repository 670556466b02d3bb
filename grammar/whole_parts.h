#pragma once
// Separate parts a grid keeps whole. Grid planes cross the whole model, so a row of repeated
// parts finds no grid when other parts that do not repeat with it lie across the planes (the
// figures on one rod of a table football among the other rods' figures). Such parts can be kept
// whole, the grid's planes cutting only the rest of the model, each placed once with the grid's
// head or moved with its tail. Their surroundings then stay as in the exemplar: what lies around
// a part moves with it, or is a copy of the same unit of the rest, as long as no part comes within
// r of the other side (grid_rules.cpp bounds the counts for that). Parts near each other (within
// about 2 r) move together.

#include "geometry/prepared_model.h"
#include "symmetry/symmetry_detection.h"

#include <cstdint>
#include <vector>

namespace dg {

/// The separate parts of a mesh: its vertex-connected components.
struct ModelParts {
  std::vector<std::uint32_t> part;  ///< per triangle: its part
  std::vector<double> area;         ///< per part, model units^2
  std::vector<BoundingBox> box;     ///< per part
};

/// The parts of `mesh` with their areas and bounding boxes.
ModelParts model_parts(const TriangleMesh& mesh);

struct WholeParts {
  std::vector<char> kept;            ///< per part (ModelParts): kept whole
  std::vector<std::uint32_t> group;  ///< per part kept whole: the parts it moves with share the number
  /// The model without the parts kept whole (mesh, feature edges, voxel surface on the same grid,
  /// the whole model's bounds), and the motion with its symmetric region on that rest.
  PreparedModel rest;
  DetectedSymmetry motion;
  bool empty() const;
};

/// Largest part (share of the model's surface area) that may be kept whole: the rest of the
/// model must be what the grid repeats.
inline constexpr double kWholePartShare = 0.05;

/// The parts of `prepared`'s mesh that a grid along `symmetry`'s translation may keep whole:
/// parts of at most kWholePartShare of the model's area that do not repeat under the motion (a
/// cell holding only their triangles is not symmetric), with the rest of the model and the
/// motion's symmetric region on it (every cell of the rest tested). Empty when no part has a copy
/// moved by the translation (there is no row of parts) or none can be kept whole.
/// `parts` are the model_parts of the prepared mesh; cells are matched with `matching` (the
/// tolerances the symmetry was detected with, SymmetryResult::region).
WholeParts whole_parts(const PreparedModel& prepared, const ModelParts& parts, const DetectedSymmetry& symmetry,
                       const RegionOptions& matching);

}  // namespace dg
