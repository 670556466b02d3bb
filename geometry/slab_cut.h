#pragma once
// Cutting a mesh along parallel planes, so every triangle lies in one slab between two planes.
// Grid pieces (corners, borders, repeated units) are cut this way.

#include "geometry/mesh.h"

#include <cstdint>
#include <vector>

namespace dg {

/// Splits the triangles of `mesh` along the planes direction . x = cuts[i] (direction unit,
/// model units). An edge crossing a plane gets one new vertex shared by both of its triangles,
/// so a closed mesh stays closed; vertices within `tolerance` of a plane are moved onto it.
/// Every piece keeps its triangle's material. The result keeps the input's vertices first, in their order. With `origin` (one entry per
/// input triangle, e.g. 0 .. n-1), it is replaced by one entry per output triangle: the entry of
/// the input triangle it was cut from.
TriangleMesh cut_along_planes(const TriangleMesh& mesh, const Vec3& direction, const std::vector<double>& cuts,
                              double tolerance, std::vector<std::uint32_t>* origin = nullptr);

/// Index of the slab holding triangle t of `mesh`, judged by its centroid: 0 below cuts[0],
/// i between cuts[i-1] and cuts[i], cuts.size() above the last (cuts ascending).
std::size_t slab_of(const TriangleMesh& mesh, std::size_t t, const Vec3& direction, const std::vector<double>& cuts);

/// Area on the side direction . x <= s of the plane at s of a triangle with area `area` whose
/// corners lie at positions s0 <= s1 <= s2 along the direction (model units).
double triangle_area_below(double s0, double s1, double s2, double area, double s);

/// The slabs of `mesh` between the planes direction . x = start + k pitch and start + (k + 1)
/// pitch (direction unit, pitch > 0, model units), found in one pass over the mesh: per slab k,
/// the triangles lying partly strictly between its planes and their area between them. The mesh
/// must outlive the table.
class SlabTable {
 public:
  SlabTable(const TriangleMesh& mesh, const Vec3& direction, double start, double pitch);
  /// Surface area in slab k (model units^2; 0 for a slab the mesh does not reach).
  double area(int k) const;
  /// The triangles reaching slab k cut along both of its planes, those between them kept (with
  /// their materials; vertices within `tolerance` of a plane moved onto it). Empty for a slab the
  /// mesh does not reach.
  TriangleMesh mesh(int k, double tolerance) const;

 private:
  const TriangleMesh& mesh_;
  Vec3 direction_;
  double start_ = 0.0, pitch_ = 0.0;
  int first_ = 0;  // slab of entry 0
  std::vector<std::vector<std::size_t>> triangles_;  // per slab, ascending
  std::vector<double> areas_;
};

/// Drops the triangles of `mesh` with a repeated corner (index); the others keep their order
/// and materials.
void drop_repeated_corners(TriangleMesh& mesh);

}  // namespace dg
