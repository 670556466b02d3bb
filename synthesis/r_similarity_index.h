#pragma once
// Point samples and exact surface queries on one mesh, the data r-similarity matching works on:
// dense area-uniform samples (with normals) found by radius, optionally only those on the part
// of the surface inside the ball that is connected to its centre, and "is there surface here?"
// and closest-point queries against the exact triangles (through a grid of triangle lists).

#include "geometry/mesh.h"

#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

namespace dg {

/// A point on the surface with the unit normal of its triangle.
struct SurfacePoint {
  Vec3 position = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
};

class SurfaceIndex {
 public:
  /// Samples `mesh` with about one point per spacing^2 of area, each triangle seeded from
  /// (seed, triangle index) so the result is deterministic. Radius queries are fastest for radii
  /// up to `gather_radius`; surface queries take cutoffs up to `max_cutoff` (model units).
  SurfaceIndex(const TriangleMesh& mesh, double spacing, double gather_radius, double max_cutoff, std::uint64_t seed);

  /// Dense samples, ordered by spatial bucket.
  const std::vector<SurfacePoint>& samples() const { return samples_; }

  /// Indices of the dense samples within `radius` (model units) of p, ascending.
  void gather(const Vec3& p, double radius, std::vector<std::uint32_t>& out) const;

  /// The intrinsic r-neighbourhood of a surface point p: indices of the dense samples within
  /// `radius` of p (ascending) whose triangles belong to the part of the surface inside that
  /// ball connected to p within the ball (through edges crossing the ball and vertices inside
  /// it). p's own triangle is the closest one within `seed_cutoff` (at most max_cutoff) whose
  /// unit normal n has n . normal >= min_cos; returns false (and `out` empty) when there is none.
  /// With `part`, also the triangles of that connected part, ascending.
  bool gather_connected(const Vec3& p, const Vec3& normal, double radius, double seed_cutoff, double min_cos,
                        std::vector<std::uint32_t>& out, std::vector<std::uint32_t>* part = nullptr) const;

  /// True when one of `triangles` (ascending indices) passes within `cutoff` (model units, at
  /// most max_cutoff) of q.
  bool near_any_of(const Vec3& q, double cutoff, const std::vector<std::uint32_t>& triangles) const;

  /// True when a triangle passes within `tolerance` (model units, at most max_cutoff) of q
  /// and its unit normal n has n . normal >= min_cos.
  bool touches(const Vec3& q, const Vec3& normal, double tolerance, double min_cos) const;

  /// Closest point to q on the triangles within `cutoff` (at most max_cutoff) whose normal
  /// n has n . normal >= min_cos, with that triangle's normal; empty when there is none.
  std::optional<SurfacePoint> closest(const Vec3& q, const Vec3& normal, double cutoff, double min_cos) const;

  /// Index of the triangle that closest() would use; empty when there is none.
  std::optional<std::uint32_t> closest_triangle(const Vec3& q, const Vec3& normal, double cutoff, double min_cos) const;

 private:
  using Key = std::uint64_t;
  using Range = std::pair<std::uint32_t, std::uint32_t>;
  static Key key(const Vec3& p, double cell);
  void build_triangle_grid(double max_cutoff);
  void build_vertex_triangles();
  template <class Visit>
  bool visit_triangles(const Vec3& q, Visit&& visit) const;

  const TriangleMesh& mesh_;
  double cell_ = 1.0;           // sample bucket size
  double triangle_cell_ = 1.0;  // triangle grid cell size (= 2 max_cutoff)
  std::vector<Vec3> triangle_normals_;
  std::vector<SurfacePoint> samples_;
  std::vector<std::uint32_t> sample_triangles_;      // triangle of each sample
  std::vector<std::uint32_t> vertex_offsets_;        // triangles around vertex v: vertex_triangles_[offsets[v] .. offsets[v+1])
  std::vector<std::uint32_t> vertex_triangles_;
  std::unordered_map<Key, Range> buckets_;           // key -> sample range
  std::vector<std::uint32_t> cell_triangles_;
  std::unordered_map<Key, Range> triangle_buckets_;  // key -> range of cell_triangles_
};

/// splitmix64: a small, well-mixed 64-bit hash (per-triangle random streams, fixed shuffles).
std::uint64_t splitmix64(std::uint64_t x);

/// Closest point to p on triangle (a, b, c) (Ericson, Real-Time Collision Detection 5.1.5).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace dg
