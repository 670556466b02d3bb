#pragma once
// Generated assets with materials, for tests that follow materials through the pipeline: each
// triangle gets the material a rule gives its centroid and normal, and the rule is the ground
// truth.

#include "geometry/mesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace dg::test {

/// Materials of the material fence: 0 "wood" (posts), 1 "metal" (rails), 2 "cap" (end-post caps).
inline constexpr std::uint32_t kWood = 0, kMetal = 1, kCap = 2;

/// The material of the fence surface around point p (assets' fence, any n): rails where
/// |y| <= 0.02 and z lies in a rail's height, caps at and above z = 1.4, posts elsewhere. Only
/// y and z matter, so it holds for every fence length. The normal is not needed.
std::uint32_t fence_material_at(const Vec3& p, const Vec3& normal = Vec3::Zero());

/// The generator's fence(n) with each triangle's material from fence_material_at (centroid).
Model material_fence(int n);

/// Materials of the material facade: 0 "plaster", 1 "glass" (the back of each window recess),
/// 2 "oak" (the back of each door recess).
inline constexpr std::uint32_t kPlaster = 0, kGlass = 1, kOak = 2;

/// The material of the facade surface around point p with unit normal `normal` (assets'
/// facade, any size): glass facing -y in the plane y = 0.15 of the window backs, oak facing -y
/// in the plane y = 0.2 of the door backs, plaster elsewhere. Only y and the normal matter, so
/// it holds for every number of columns and rows.
std::uint32_t facade_material_at(const Vec3& p, const Vec3& normal);

/// The generator's facade(columns, rows) with each triangle's material from facade_material_at.
Model material_facade(int columns, int rows);

/// Cell size of the painted wall along x and y, model units.
inline constexpr double kPaintedPitchX = 3.0, kPaintedPitchY = 2.0;

/// A flat wall in z = 0 facing +z of `columns` x `rows` cells of kPaintedPitchX x kPaintedPitchY,
/// each a window [0.75, 2.25] x [0.5, 1.5] (material 1 "glass") framed by wall (material 0
/// "wall"), drawn as 3 x 3 rectangles of two triangles per cell (welded by cleaning).
Model painted_wall(int columns, int rows);

/// Height of one stripe of the striped wall, the wall's width and the height of its foot, model
/// units. The foot keeps stripe borders off the faces of voxels whose size divides 0.5.
inline constexpr double kStripeHeight = 1.5, kStripedWallWidth = 12.0, kStripedWallFoot = 0.25;

/// A flat wall in z = 0 facing +z, kStripedWallWidth wide, of horizontal stripes kStripeHeight
/// tall: stripe i spans y from kStripedWallFoot + i kStripeHeight and has material
/// stripe_materials[i]. The
/// materials are named `names` (indexed by material), each stripe is four rectangles along x.
Model striped_wall(const std::vector<std::uint32_t>& stripe_materials, const std::vector<std::string>& names);

/// The painted wall's material around point p: glass inside a cell's window, wall elsewhere.
/// Periodic in x and y, so it holds for every size.
std::uint32_t painted_wall_material_at(const Vec3& p);

}  // namespace dg::test
