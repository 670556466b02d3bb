#pragma once
// A fence with three materials, for tests that follow materials through the pipeline.

#include "geometry/mesh.h"

#include <cstdint>

namespace dg::test {

/// Materials of the material fence: 0 "wood" (posts), 1 "metal" (rails), 2 "cap" (end-post caps).
inline constexpr std::uint32_t kWood = 0, kMetal = 1, kCap = 2;

/// The material of the fence surface around point p (assets' fence, any n): rails where
/// |y| <= 0.02 and z lies in a rail's height, caps at and above z = 1.4, posts elsewhere. Only
/// y and z matter, so it holds for every fence length.
std::uint32_t fence_material_at(const Vec3& p);

/// The generator's fence(n) with each triangle's material from fence_material_at (centroid).
Model material_fence(int n);

}  // namespace dg::test
