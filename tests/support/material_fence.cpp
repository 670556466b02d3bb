#include "support/material_fence.h"

#include "assets/generator/asset.h"

#include <cmath>

namespace dg::test {

std::uint32_t fence_material_at(const Vec3& p) {
  constexpr double tolerance = 1e-9;
  const bool in_rail_height = (p.z() >= 0.30 - tolerance && p.z() <= 0.38 + tolerance) ||
                              (p.z() >= 0.90 - tolerance && p.z() <= 0.98 + tolerance);
  if (std::abs(p.y()) <= 0.02 + tolerance && in_rail_height) return kMetal;
  if (p.z() >= 1.40 - tolerance) return kCap;
  return kWood;
}

Model material_fence(int n) {
  Model model;
  model.mesh = assets::make_asset("fence", {{"n", n}}).mesh;
  model.materials = {{"wood", Vec3(0.55, 0.35, 0.2)}, {"metal", Vec3(0.5, 0.5, 0.55)}, {"cap", Vec3(0.1, 0.1, 0.1)}};
  for (std::size_t t = 0; t < model.mesh.triangles.size(); ++t) {
    const auto [a, b, c] = model.mesh.corners(t);
    model.mesh.materials.push_back(fence_material_at((a + b + c) / 3.0));
  }
  return model;
}

}  // namespace dg::test
