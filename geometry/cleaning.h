#pragma once
// Cleaning a freshly read model: exact weld, dropping degenerate triangles and unused
// vertices, and a report of what the input looked like (for `info` and --json output).

#include "geometry/mesh.h"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>

namespace dg {

/// Knobs of clean_mesh.
struct CleaningOptions {
  /// A triangle is degenerate when |(b - a) x (c - a)| <= collinear_tolerance * L^2, L = its longest
  /// edge. |cross| = L * h with h the height over the longest edge, so this drops triangles whose
  /// height is below 1e-12 of their longest edge (zero area, or corners collinear up to rounding).
  /// Triangles with a repeated vertex index (after welding) are always degenerate; a negative
  /// tolerance turns the geometric test off so that only those count.
  double collinear_tolerance = 1e-12;
  /// Drop degenerate triangles (default). When false they are only counted.
  bool drop_degenerate = true;
};

/// What cleaning found. Edge and component counts describe the mesh after cleaning.
/// For point clouds the vertex fields count points and the triangle/edge fields stay 0.
struct CleaningReport {
  bool point_cloud = false;
  std::size_t input_vertices = 0;       ///< positions (points) as read
  std::size_t input_triangles = 0;      ///< triangles as read (after triangulating polygons)
  std::size_t welded_vertices = 0;      ///< distinct positions after the exact weld (points: after de-duplication)
  std::size_t vertices = 0;             ///< positions (points) in the cleaned model
  std::size_t triangles = 0;            ///< triangles in the cleaned mesh
  std::size_t degenerate_dropped = 0;   ///< degenerate triangles (see CleaningOptions), dropped unless disabled
  std::size_t duplicate_triangles = 0;  ///< extra copies of a vertex set (either orientation); kept
  std::size_t non_manifold_edges = 0;   ///< edges used by 3 or more triangles
  std::size_t boundary_edges = 0;       ///< edges used by exactly one triangle
  std::size_t inconsistent_edges = 0;   ///< two-triangle edges traversed the same way by both
  std::size_t components = 0;           ///< vertex-connected triangle components
  bool closed_and_oriented = false;     ///< every edge has exactly two opposite uses
  std::size_t duplicate_points_dropped = 0;  ///< point clouds: exact repeats of an earlier point
  std::size_t invalid_normals_dropped = 0;   ///< point clouds: points whose normal is non-finite or zero
  BoundingBox bounds;                   ///< bounds of the cleaned model, model units
  /// Set by prepare_model after the counts above: open edges split at a vertex lying on them
  /// (T-junctions, e.g. a fan whose edge skips a vertex of the neighbouring face).
  std::size_t t_junctions_split = 0;
};

/// Whether clean_mesh counts triangle t of `mesh` as degenerate: a repeated vertex index, or
/// corners collinear within `collinear_tolerance` (see CleaningOptions).
bool is_degenerate(const TriangleMesh& mesh, const Triangle& t, double collinear_tolerance = CleaningOptions{}.collinear_tolerance);

/// The geometric part of that test for corners a, b, c: |(b - a) x (c - a)| <= tolerance * L^2,
/// L the longest edge.
bool nearly_collinear(const Vec3& a, const Vec3& b, const Vec3& c, double collinear_tolerance = CleaningOptions{}.collinear_tolerance);

/// Cleans `mesh` in place: welds vertices with exactly equal positions (the first occurrence
/// keeps its place; surviving vertices keep their relative order), drops degenerate triangles,
/// then drops vertices no triangle uses. Triangle order (and each triangle's material) is kept.
/// Positions must be finite.
CleaningReport clean_mesh(TriangleMesh& mesh, const CleaningOptions& options = {});

/// Cleans `cloud` in place: drops points whose normal is non-finite or zero (when normals exist),
/// scales the other normals to unit length, then drops exact repeats of an earlier position.
CleaningReport clean_point_cloud(PointCloud& cloud);

/// The report as a JSON object (keys as the field names; mesh or point-cloud fields by kind).
nlohmann::json to_json(const CleaningReport& report);

}  // namespace dg
