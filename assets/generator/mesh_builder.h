#pragma once
// Building an indexed triangle mesh whose vertices are welded by exact position, so that parts
// computed from the same formulas share vertices and close up without T-junctions.

#include "geometry/mesh.h"

#include <cstdint>
#include <unordered_map>

namespace dg::assets {

/// Collects triangles; a vertex is created once per distinct position (bitwise equal, with
/// -0 and +0 identified). Positions keep their order of first use.
class MeshBuilder {
 public:
  /// Index of the vertex at p, created on first use.
  std::uint32_t vertex(const Vec3& p);
  /// Adds triangle a, b, c (counter-clockwise seen from the front).
  void triangle(const Vec3& a, const Vec3& b, const Vec3& c);
  /// Adds the planar convex quad a, b, c, d (counter-clockwise) as triangles a b c and a c d.
  void quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
  /// Moves the finished mesh out; the builder is empty afterwards.
  TriangleMesh take();

 private:
  struct KeyHash {
    std::size_t operator()(const Vec3& p) const;
  };
  struct KeyEqual {
    bool operator()(const Vec3& a, const Vec3& b) const { return a == b; }
  };
  TriangleMesh mesh_;
  std::unordered_map<Vec3, std::uint32_t, KeyHash, KeyEqual> index_;
};

}  // namespace dg::assets
