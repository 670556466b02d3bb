#pragma once
// Classification of mesh edges into boundary, sharp (feature) and non-manifold edges.

#include "geometry/mesh.h"

#include <cstdint>
#include <span>
#include <vector>

namespace dg {

/// Default dihedral threshold in degrees: an edge is sharp when the normals of its two
/// triangles differ by more than this angle.
inline constexpr double kDefaultSharpAngleDegrees = 35.0;

/// boundary: one triangle; sharp: dihedral above the threshold; non_manifold: three or more
/// triangles; material: a smooth edge between triangles of different materials (a window's outline
/// drawn on a flat wall), a feature like a crease.
enum class EdgeKind : std::uint8_t { boundary, sharp, non_manifold, material };

/// An undirected mesh edge that feature lines and cells care about.
struct FeatureEdge {
  std::uint32_t v0 = 0, v1 = 0;  ///< vertex indices, v0 < v1
  EdgeKind kind = EdgeKind::sharp;
  double dihedral_degrees = 0.0;  ///< angle between the face normals (0 for boundary edges);
                                  ///< negative when the edge is concave (a valley)
  Vec3 normal = Vec3::Zero();     ///< unit average of the adjacent face normals
};

/// Boundary, sharp and non-manifold edges of a welded mesh, sorted by (v0, v1); with
/// `material_classes` (the matching class of each material index, see material_classes(); empty =
/// none) and a mesh that has materials, also the edges between materials of different classes.
/// Exact duplicate triangles (same vertex set, either orientation) are counted once, so
/// back-to-back double faces do not turn every edge into a feature.
std::vector<FeatureEdge> find_feature_edges(const TriangleMesh& mesh,
                                            double sharp_angle_degrees = kDefaultSharpAngleDegrees,
                                            std::span<const std::uint32_t> material_classes = {});

}  // namespace dg
