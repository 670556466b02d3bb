#pragma once
// Flat regions of a triangle mesh: its flat faces of one material that lie in one plane and face
// the same side, taken together, with the outline of their union. Cutting a mesh apart and
// merging its pieces again splits a flat face into parts that meet only at T-junctions, in
// different ways from copy to copy; the region and its outline stay the same.

#include "geometry/mesh.h"
#include "geometry/rigid_transform.h"
#include "geometry/segment_index.h"

#include <cstdint>
#include <vector>

namespace dg {

/// Flat faces (see flat_faces) of one material, side up and plane, with their outline.
struct FlatRegion {
  std::vector<std::uint32_t> triangles;  ///< ascending
  std::uint32_t material = 0;            ///< 0 for a mesh without materials
  Vec3 normal = Vec3::Zero();            ///< unit: the direction of the summed area vectors
  double area = 0.0;                     ///< model units^2
  BoundingBox bounds;
  /// The faces' outline edges, split where another outline vertex lies on them, without the
  /// parts that an even number of the faces use (where two faces meet, also at a T-junction):
  /// each as its two end points.
  std::vector<Segment> outline;
};

/// Which coplanar flat faces form one region: all of them (faces a cut split apart, meeting only at
/// T-junctions, and also faces far apart that happen to lie in one plane), or only those joined
/// through shared corners (a stair's top tread, not the baluster top in its plane further down).
enum class FlatJoin { coplanar, sharing_corners };

/// The flat regions of `mesh` made of the flat faces that hold a triangle flagged in `wanted` (one
/// flag per triangle; faces and planes within kFlatFraction of the mesh's bounding-box
/// diagonal), in order of their first flagged triangle.
std::vector<FlatRegion> flat_regions(const TriangleMesh& mesh, const std::vector<char>& wanted, FlatJoin join = FlatJoin::coplanar);

/// `region` (a flat region of `mesh`) moved by `motion`: normal, bounds and outline moved; its
/// triangles still index `mesh`.
FlatRegion moved_region(const FlatRegion& region, const TriangleMesh& mesh, const RigidTransform& motion);

/// Whether flat regions x and y are one region, however each is triangulated: the same material
/// and side up, bounding boxes within `distance` (model units), each outline's ends within
/// `distance` of the other's plane, every point of each outline (sampled every distance / 4)
/// within `distance` of the other outline, and areas that differ by no more than `distance`
/// times the longer outline. A plane and an outline fix the region they bound.
bool same_flat_region(const FlatRegion& x, const FlatRegion& y, double distance);

}  // namespace dg
