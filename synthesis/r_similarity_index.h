#pragma once
// Point samples and exact surface queries on one surface, the data r-similarity matching works on:
// dense samples (with normals) found by radius, optionally only those on the part of the surface
// inside the ball that is connected to its centre, and "is there surface here?" and closest-point
// queries against the surface's elements (through a grid of element lists). The elements of a
// mesh are its triangles; those of a point cloud are its points, each a small disk in its
// tangent plane (a splat) whose normal has no sign.

#include "geometry/cell_ranges.h"
#include "geometry/closest_point.h"
#include "geometry/mesh.h"
#include "geometry/point_grid.h"

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
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

  /// A point cloud with unit normals (InputError without them): each point is a disk of radius
  /// `splat_radius` in its tangent plane, normals agree up to sign, the samples are the points
  /// thinned to the first in each cube of edge `spacing`, and the connected part of a ball links
  /// points closer than 2 x splat_radius (model units).
  SurfaceIndex(const PointCloud& cloud, double splat_radius, double spacing, double gather_radius, double max_cutoff);

  SurfaceIndex(const SurfaceIndex&) = delete;
  SurfaceIndex& operator=(const SurfaceIndex&) = delete;
  ~SurfaceIndex();

  /// True for a point cloud (unoriented normals).
  bool is_cloud() const { return cloud_ != nullptr; }

  /// Whether two unit normals agree within the angle whose cosine is min_cos (up to sign for a cloud).
  bool normals_agree(const Vec3& a, const Vec3& b, double min_cos) const {
    const double c = a.dot(b);
    return (is_cloud() ? std::abs(c) : c) >= min_cos;
  }

  /// Dense samples, ordered by spatial bucket.
  const std::vector<SurfacePoint>& samples() const { return samples_; }

  /// Indices of the dense samples within `radius` (model units) of p, ascending.
  void gather(const Vec3& p, double radius, std::vector<std::uint32_t>& out) const;

  /// The intrinsic r-neighbourhood of a surface point p: indices of the dense samples within
  /// `radius` of p (ascending) whose elements belong to the part of the surface inside that
  /// ball connected to p within the ball (a mesh: through edges crossing the ball and vertices
  /// inside it; a cloud: through points inside it closer than the link distance). p's own
  /// element is the closest one within `seed_cutoff` (at most max_cutoff) whose normal agrees
  /// with `normal` (normals_agree); returns false (and `out` empty) when there is none.
  /// With `part`, also the elements of that connected part, ascending.
  bool gather_connected(const Vec3& p, const Vec3& normal, double radius, double seed_cutoff, double min_cos,
                        std::vector<std::uint32_t>& out, std::vector<std::uint32_t>* part = nullptr) const;

  /// True when one of `elements` (ascending indices) passes within `cutoff` (model units, at
  /// most max_cutoff) of q.
  bool near_any_of(const Vec3& q, double cutoff, const std::vector<std::uint32_t>& elements) const;

  /// True when an element passes within `tolerance` (model units, at most max_cutoff) of q
  /// and its normal agrees with `normal` (normals_agree).
  bool touches(const Vec3& q, const Vec3& normal, double tolerance, double min_cos) const;

  /// Closest point to q on the elements within `cutoff` (at most max_cutoff) whose normal
  /// agrees with `normal`, with that element's normal; empty when there is none.
  std::optional<SurfacePoint> closest(const Vec3& q, const Vec3& normal, double cutoff, double min_cos) const;

  /// Index of the element that closest() would use; empty when there is none.
  std::optional<std::uint32_t> closest_element(const Vec3& q, const Vec3& normal, double cutoff, double min_cos) const;

 private:
  using Key = std::uint64_t;
  static Key key(const Vec3& p, double cell);
  void set_samples(std::vector<SurfacePoint> points, std::vector<std::uint32_t> elements);
  void build_triangle_grid(double max_cutoff);
  void build_vertex_triangles();
  Vec3 closest_on_element(std::uint32_t element, const Vec3& q) const;
  void connected_triangles(const Vec3& p, double radius, std::vector<std::uint32_t>& component) const;
  void connected_points(const Vec3& p, double radius, std::vector<std::uint32_t>& component) const;
  template <class Visit>
  bool visit_elements(const Vec3& q, Visit&& visit) const;

  const TriangleMesh* mesh_ = nullptr;
  const PointCloud* cloud_ = nullptr;
  double splat_radius_ = 0.0;          // cloud: disk radius of a point
  double cell_ = 1.0;                  // sample bucket size
  double triangle_cell_ = 1.0;         // mesh: triangle grid cell size (= 2 max_cutoff)
  double point_reach_ = 0.0;           // cloud: max_cutoff + splat radius
  std::vector<Vec3> element_normals_;  // mesh: triangle normals; cloud: point normals
  std::vector<SurfacePoint> samples_;
  std::vector<std::uint32_t> sample_elements_;   // element of each sample
  std::vector<std::uint32_t> vertex_offsets_;    // mesh: triangles around vertex v: vertex_triangles_[offsets[v] .. offsets[v+1])
  std::vector<std::uint32_t> vertex_triangles_;
  std::unique_ptr<PointGrid> point_grid_;        // cloud: points by cells of point_reach_
  CellRanges buckets_;                           // key -> sample range
  std::vector<std::uint32_t> cell_triangles_;
  CellRanges triangle_buckets_;                  // mesh: key -> range of cell_triangles_
};

/// splitmix64: a small, well-mixed 64-bit hash (per-triangle random streams, fixed shuffles).
std::uint64_t splitmix64(std::uint64_t x);

}  // namespace dg
