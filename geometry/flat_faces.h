#pragma once
// Flat faces of a triangle mesh: edge-joined triangles of one material that lie in one plane.
// Cutting and assembling pieces leaves flat faces split into many triangles along seams that
// are no longer seams; merging re-triangulates each face with as few triangles as its outline
// allows.

#include "geometry/mesh.h"

#include <cstdint>
#include <vector>

namespace dg {

/// Distance from a face's plane, relative to the mesh's bounding-box diagonal, within which a
/// corner counts as lying in it. Text formats keep 6 or 7 significant digits, so the flat faces
/// of real assets are flat only to about 1e-7 of their size; modelled detail is far larger.
inline constexpr double kFlatFraction = 1e-6;

/// One id per triangle of `mesh` (the index of one triangle of its group): triangles share an id
/// when edges join them, they face the same side, share their material and their `kind` flag
/// (one per triangle; empty = all alike), and each one's corners lie within `tolerance` (model
/// units) of the other's plane. An edge joins its two users, or, when more use it, two that lie
/// flat so with each other only (each side of a double-sided face stays one face).
std::vector<std::uint32_t> flat_faces(const TriangleMesh& mesh, const std::vector<char>& kind, double tolerance);

/// What more merge_flat_faces may do.
struct FlatFaceMergeOptions {
  /// Also drop vertices inside one flat face where two open edges meet in a straight line (a
  /// piece's seam, which a mesh welded to it later closes, see resolve_t_junctions).
  bool straighten_open_borders = false;
  /// How far (model units) earlier cuts may have moved a vertex off a face's outline (see
  /// FragmentMergeOptions::moved_distance); the plane tolerance when smaller.
  double moved_distance = 0.0;
};

/// `mesh` with each flat face (see flat_faces, within 1e-6 of the mesh's bounding-box diagonal;
/// `kind` all alike) re-triangulated from its outline: vertices inside a face go, and so do
/// vertices where exactly two face outlines meet in a straight line (both faces drop them, so
/// the mesh stays conforming). Corners, vertices on open and non-manifold edges and vertices of
/// curved areas stay; a face whose re-triangulation would change its area by more than the
/// moved distance times its outline's length keeps its triangles and all their vertices. Unused
/// vertices are removed; materials travel with the triangles. Deterministic.
TriangleMesh merge_flat_faces(const TriangleMesh& mesh, const FlatFaceMergeOptions& options = {});

}  // namespace dg
