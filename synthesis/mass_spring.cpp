#include "synthesis/mass_spring.h"

#include <algorithm>
#include <map>

namespace dg {

namespace {

struct Spring {
  std::size_t a = 0, b = 0;
  double rest = 0;
  double stiffness = 1;
};

// Particles: one per distinct vertex position (snapped guides share them); ids per guide vertex.
struct Particles {
  std::vector<Vec2> positions;
  std::vector<std::vector<std::size_t>> of_guide;  // [guide][vertex] -> particle
};

Particles make_particles(const GrowthScene& scene) {
  Particles particles;
  std::map<std::pair<double, double>, std::size_t> by_position;
  for (const Guide& guide : scene.guides) {
    std::vector<std::size_t> ids;
    for (const Vec2& v : guide.polygon) {
      const auto [it, added] = by_position.try_emplace({v.x(), v.y()}, particles.positions.size());
      if (added) particles.positions.push_back(v);
      ids.push_back(it->second);
    }
    particles.of_guide.push_back(std::move(ids));
  }
  return particles;
}

std::vector<Spring> make_springs(const GrowthScene& scene, const Particles& particles) {
  const SpringSettings& settings = scene.springs;
  std::vector<Spring> springs;
  auto add = [&](std::size_t a, std::size_t b, double stiffness) {
    if (a == b || stiffness <= 0) return;
    springs.push_back({a, b, (particles.positions[a] - particles.positions[b]).norm(), stiffness});
  };
  for (const std::vector<std::size_t>& ids : particles.of_guide) {
    const std::size_t n = ids.size();
    for (std::size_t i = 0; i < n; ++i) {
      add(ids[i], ids[(i + 1) % n], settings.edge_stiffness);
      for (std::size_t j = i + 2; j < n; ++j)
        if (!(i == 0 && j == n - 1)) add(ids[i], ids[j], settings.diagonal_stiffness);
    }
  }
  auto vertex = [&](std::size_t guide, std::size_t v) {
    return particles.of_guide[guide][v % particles.of_guide[guide].size()];
  };
  if (settings.link_springs)
    for (const GuideLink& link : scene.links) {
      const std::size_t a = vertex(link.from_guide, link.from_edge), b = vertex(link.from_guide, link.from_edge + 1);
      const std::size_t c = vertex(link.to_guide, link.to_edge), d = vertex(link.to_guide, link.to_edge + 1);
      for (const auto& [p, q] : {std::pair{a, c}, {a, d}, {b, c}, {b, d}}) add(p, q, settings.link_stiffness);
    }
  for (const GuideSpring& spring : settings.springs)
    add(vertex(spring.guide_a, spring.vertex_a), vertex(spring.guide_b, spring.vertex_b), settings.link_stiffness);
  return springs;
}

}  // namespace

std::vector<std::size_t> drag_guide_vertex(GrowthScene& scene, std::size_t guide, std::size_t vertex, const Vec2& target) {
  Particles particles = make_particles(scene);
  const std::vector<Spring> springs = make_springs(scene, particles);
  const std::vector<Vec2> before = particles.positions;
  std::vector<char> fixed(particles.positions.size(), 0);
  for (const auto& [g, v] : scene.springs.pinned) fixed[particles.of_guide[g][v]] = 1;
  const std::size_t dragged = particles.of_guide[guide][vertex];
  fixed[dragged] = 1;
  particles.positions[dragged] = target;

  double stiffest = 0;
  for (const Spring& spring : springs) stiffest = std::max(stiffest, spring.stiffness);
  std::vector<Vec2>& x = particles.positions;
  for (int sweep = 0; sweep < scene.springs.iterations; ++sweep)
    for (const Spring& spring : springs) {
      const Vec2 d = x[spring.b] - x[spring.a];
      const double length = d.norm();
      if (length == 0) continue;
      const double weight_a = fixed[spring.a] ? 0 : 1, weight_b = fixed[spring.b] ? 0 : 1;
      if (weight_a + weight_b == 0) continue;
      const Vec2 correction = (spring.stiffness / stiffest) * (length - spring.rest) / length / (weight_a + weight_b) * d;
      x[spring.a] += weight_a * correction;
      x[spring.b] -= weight_b * correction;
    }

  double extent = 0;
  for (const Vec2& p : before) extent = std::max(extent, p.cwiseAbs().maxCoeff());
  const double tolerance = 1e-9 * std::max(extent, 1.0);
  std::vector<std::size_t> changed;
  for (std::size_t g = 0; g < scene.guides.size(); ++g) {
    Guide& moved = scene.guides[g];
    const std::vector<std::size_t>& ids = particles.of_guide[g];
    bool any = false;
    for (std::size_t v = 0; v < ids.size(); ++v) any = any || (x[ids[v]] - before[ids[v]]).norm() > tolerance;
    if (!any) continue;
    changed.push_back(g);
    for (GuideSeed& seed : moved.seeds) {
      std::size_t nearest = 0;
      for (std::size_t v = 1; v < ids.size(); ++v)
        if ((before[ids[v]] - seed.position).norm() < (before[ids[nearest]] - seed.position).norm()) nearest = v;
      seed.position += x[ids[nearest]] - before[ids[nearest]];
    }
    for (std::size_t v = 0; v < ids.size(); ++v) moved.polygon[v] = x[ids[v]];
  }
  return changed;
}

}  // namespace dg
