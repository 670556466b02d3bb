#include "support/material_models.h"

#include "assets/generator/asset.h"

#include <cmath>

namespace dg::test {
namespace {

constexpr double kTolerance = 1e-9;

// `mesh` with `materials` and each triangle's material from `rule` at its centroid and normal.
template <class Rule>
Model with_materials(TriangleMesh mesh, std::vector<Material> materials, Rule rule) {
  Model model;
  model.mesh = std::move(mesh);
  model.materials = std::move(materials);
  for (std::size_t t = 0; t < model.mesh.triangles.size(); ++t) {
    const auto [a, b, c] = model.mesh.corners(t);
    model.mesh.materials.push_back(rule((a + b + c) / 3.0, model.mesh.area_vector(t).normalized()));
  }
  return model;
}

}  // namespace

std::uint32_t fence_material_at(const Vec3& p, const Vec3&) {
  const bool in_rail_height = (p.z() >= 0.30 - kTolerance && p.z() <= 0.38 + kTolerance) ||
                              (p.z() >= 0.90 - kTolerance && p.z() <= 0.98 + kTolerance);
  if (std::abs(p.y()) <= 0.02 + kTolerance && in_rail_height) return kMetal;
  if (p.z() >= 1.40 - kTolerance) return kCap;
  return kWood;
}

Model material_fence(int n) {
  return with_materials(assets::make_asset("fence", {{"n", n}}).mesh,
                        {{"wood", Vec3(0.55, 0.35, 0.2)}, {"metal", Vec3(0.5, 0.5, 0.55)}, {"cap", Vec3(0.1, 0.1, 0.1)}},
                        [](const Vec3& p, const Vec3& normal) { return fence_material_at(p, normal); });
}

std::uint32_t facade_material_at(const Vec3& p, const Vec3& normal) {
  if (normal.y() > -0.5) return kPlaster;
  if (std::abs(p.y() - 0.15) <= kTolerance) return kGlass;
  if (std::abs(p.y() - 0.2) <= kTolerance) return kOak;
  return kPlaster;
}

Model material_facade(int columns, int rows) {
  return with_materials(assets::make_asset("facade", {{"columns", columns}, {"rows", rows}}).mesh,
                        {{"plaster", Vec3(0.9, 0.88, 0.8)}, {"glass", Vec3(0.3, 0.5, 0.7)}, {"oak", Vec3(0.4, 0.25, 0.1)}},
                        [](const Vec3& p, const Vec3& normal) { return facade_material_at(p, normal); });
}

}  // namespace dg::test
