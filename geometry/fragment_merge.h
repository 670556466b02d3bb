#pragma once
// Undoing needless splits: a triangle cut into many fragments (e.g. along voxel planes) is
// re-triangulated with as few triangles as its labelled regions allow. Fragments of one input
// triangle that carry the same label and touch along an edge form a region; each region is
// re-triangulated (constrained Delaunay) keeping only the vertices that corners, label borders
// and open edges need, so the mesh stays conforming and the labelled borders stay edges.

#include "geometry/mesh.h"

#include <cstdint>
#include <vector>

namespace dg {

/// The result of merge_fragments: the new triangles and, per new triangle, one input triangle
/// of the region it lies in (its origin, label and material are the new triangle's).
struct MergedFragments {
  TriangleMesh mesh;  ///< same positions as the input (unused ones stay)
  std::vector<std::uint32_t> representative;
};

/// Which more vertices merge_fragments may drop.
struct FragmentMergeOptions {
  /// A vertex inside one input triangle where two open edges meet in a straight line (the
  /// border keeps its shape; a mesh welded to it later must close the T-junctions, see
  /// resolve_t_junctions).
  bool straighten_open_borders = false;
  /// A vertex that is not pinned, has no open or non-manifold edge and where exactly two region
  /// borders (edges between labels or between input triangles) meet in a straight line; it goes
  /// from both regions beside it, so the mesh stays conforming (e.g. where a plane cut crossed
  /// a fragment's own diagonal).
  bool straighten_label_borders = false;
  /// How far (model units) cutting may have moved a vertex (cut_zone snaps vertices onto its
  /// planes): a region's border vertex that is not kept may lie that far off the straight
  /// border the re-triangulation follows, so its area may differ by that times the border length.
  double moved_distance = 0.0;
};

/// Re-triangulates the regions of `mesh` (fragments with equal `origin`, equal `label` and,
/// when `mesh` has materials, equal material, one of each per triangle, joined across edges
/// used by exactly two triangles, or by two of each of the input triangles using them: a face
/// the mesh holds twice, cut alike); a material border counts as a label border. Vertices
/// flagged in `pinned` (one flag per vertex, e.g. the input triangles' corners) are always
/// kept; others only where an edge between different labels, or an edge used otherwise, ends
/// (an edge of two input triangles back to back, e.g. a part resting on another, is open in both);
/// `options` lets some of those go too. Regions made of the same triangles (the copies of a
/// face held twice) are re-triangulated alike, each keeping its own facing.
/// A region keeps its fragments when its re-triangulation does not reproduce its area (within
/// 1e-9 relative, plus options.moved_distance times the length of its border), does not keep
/// its one-sided border edges as border, or would add an edge that a triangle of another region
/// already uses (other than one in the same plane: a back face, or another layer of a face the
/// mesh holds twice); its neighbours then keep every vertex of its fragments too, so the result
/// stays conforming. Deterministic.
MergedFragments merge_fragments(const TriangleMesh& mesh, const std::vector<std::uint32_t>& origin,
                                const std::vector<std::uint32_t>& label, const std::vector<char>& pinned,
                                const FragmentMergeOptions& options = {});

}  // namespace dg
