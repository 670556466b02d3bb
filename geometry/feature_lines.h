#pragma once
// Feature lines: chains of sharp, boundary and material-border edges, resampled with local frames.
// Symmetry detection pairs their samples to propose rigid transforms (paper 001 §4.1).

#include "geometry/feature_edges.h"

#include <cstdint>
#include <vector>

namespace dg {

/// Default corner angle in degrees: a chain is split where consecutive edges turn by more.
inline constexpr double kDefaultCornerAngleDegrees = 30.0;

/// A polyline of feature edges between two ends (corners, junctions, line ends) or a loop.
struct FeatureLine {
  std::vector<std::uint32_t> vertices;  ///< mesh vertex indices along the line
  std::vector<Vec3> normals;            ///< unit surface normal per edge (vertices.size() - 1)
  std::vector<double> dihedrals;        ///< signed dihedral angle per edge, degrees
  bool closed = false;                  ///< last vertex connects back to the first
  /// What the line runs along: boundary, material-border or crease edges (sharp; non-manifold
  /// edges count as creases).
  EdgeKind kind = EdgeKind::sharp;
  double length = 0.0;                  ///< model units
};

/// What a sample offers for pairing with other samples; compared with tolerances.
struct FeatureDescriptor {
  double dihedral_degrees = 0.0;  ///< signed dihedral of the edge under the sample (0 on boundaries)
  double curvature = 0.0;         ///< turning angle per unit length of the line near the sample (rad/unit)
  EdgeKind kind = EdgeKind::sharp;  ///< the kind of the line under the sample (FeatureLine::kind)
};

/// A point on a feature line with an orthonormal frame (tangent along the line, normal =
/// surface normal made orthogonal to the tangent, binormal = tangent x normal).
struct FeatureSample {
  Vec3 position, tangent, normal, binormal;
  std::uint32_t line = 0;  ///< index into FeatureLines::lines
  FeatureDescriptor descriptor;
};

struct FeatureLines {
  std::vector<FeatureLine> lines;
  std::vector<FeatureSample> samples;

  /// Sum of line lengths in model units.
  double total_length() const;
};

/// Turning angle per unit length at vertex k of the polyline `points` (radians per model unit;
/// 0 at the ends of an open one; a closed one turns at every vertex).
double vertex_curvature(const std::vector<Vec3>& points, bool closed, std::size_t k);

/// The sample of `line` (index `line_index`) at `position` on its edge `edge` (from vertex edge
/// to vertex edge + 1, wrapping on a loop), travelled along the unit `tangent` (either way along
/// the edge): normal, binormal and descriptor from that edge, the given `curvature`.
FeatureSample sample_on_edge(const FeatureLine& line, std::uint32_t line_index, std::size_t edge, const Vec3& position,
                             const Vec3& tangent, double curvature);

/// Chains `features` (from find_feature_edges on the same welded mesh) into lines, split at
/// junctions, at corners turning by more than `corner_angle_degrees`, and where edges of different
/// classes meet (boundary, material border, crease); resamples each line at a spacing of about `spacing` model units (open lines get
/// both end points). Deterministic: the result depends only on the inputs.
FeatureLines extract_feature_lines(const TriangleMesh& mesh, const std::vector<FeatureEdge>& features, double spacing,
                                   double corner_angle_degrees = kDefaultCornerAngleDegrees);

}  // namespace dg
