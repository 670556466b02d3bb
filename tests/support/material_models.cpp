#include "support/material_models.h"

#include "assets/generator/asset.h"

#include <cmath>
#include <utility>

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

// Appends the rectangle [x0, x1] x [y0, y1] in z = 0 as two triangles facing +z.
void add_rectangle(TriangleMesh& mesh, double x0, double y0, double x1, double y1, std::uint32_t material) {
  const auto base = static_cast<std::uint32_t>(mesh.positions.size());
  for (const auto& [x, y] : {std::pair{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}) mesh.positions.emplace_back(x, y, 0.0);
  mesh.triangles.push_back({base, base + 1, base + 2});
  mesh.triangles.push_back({base, base + 2, base + 3});
  mesh.materials.insert(mesh.materials.end(), 2, material);
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

Model painted_wall(int columns, int rows) {
  Model model;
  model.materials = {{"wall", Vec3(0.9, 0.9, 0.85)}, {"glass", Vec3(0.3, 0.4, 0.6)}};
  // Cell-local breaks: frame, window, frame.
  const double xs[] = {0.0, 0.75, 2.25, kPaintedPitchX}, ys[] = {0.0, 0.5, 1.5, kPaintedPitchY};
  for (int c = 0; c < columns; ++c)
    for (int r = 0; r < rows; ++r)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          add_rectangle(model.mesh, c * kPaintedPitchX + xs[i], r * kPaintedPitchY + ys[j], c * kPaintedPitchX + xs[i + 1],
                        r * kPaintedPitchY + ys[j + 1], i == 1 && j == 1 ? 1 : 0);
  return model;
}

Model striped_wall(const std::vector<std::uint32_t>& stripe_materials, const std::vector<std::string>& names) {
  Model model;
  for (const std::string& name : names) model.materials.push_back({name, Vec3(0.8, 0.8, 0.8)});
  const double quarter = kStripedWallWidth / 4.0;
  for (std::size_t i = 0; i < stripe_materials.size(); ++i)
    for (int k = 0; k < 4; ++k)
      add_rectangle(model.mesh, k * quarter, kStripedWallFoot + static_cast<double>(i) * kStripeHeight, (k + 1) * quarter,
                    kStripedWallFoot + static_cast<double>(i + 1) * kStripeHeight, stripe_materials[i]);
  return model;
}

std::uint32_t painted_wall_material_at(const Vec3& p) {
  const double x = p.x() - kPaintedPitchX * std::floor(p.x() / kPaintedPitchX);
  const double y = p.y() - kPaintedPitchY * std::floor(p.y() / kPaintedPitchY);
  return x > 0.75 && x < 2.25 && y > 0.5 && y < 1.5 ? 1 : 0;
}

}  // namespace dg::test
