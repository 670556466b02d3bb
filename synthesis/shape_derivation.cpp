#include "synthesis/shape_derivation.h"

#include "geometry/submesh.h"
#include "geometry/t_junctions.h"
#include "grammar/random.h"
#include "synthesis/piece_collision.h"

#include <deque>
#include <stdexcept>

namespace dg {
namespace {

struct OpenSlot {
  ChildSlot slot;
  RigidTransform world;  // child frame -> model
  int depth = 1;
};

SeamPlane seam_of(const ShapeNonterminal& nt, const RigidTransform& world) {
  const Vec3 normal = world.apply_direction(nt.seam_normal);
  return {normal, normal.dot(world.apply(nt.seam_offset * nt.seam_normal))};
}

// Seam planes of a production placed with `world`: its own seam and those of its slots.
std::vector<SeamPlane> seams_of(const ContextFreeGrammar& g, const ShapeProduction& p, const RigidTransform& world) {
  std::vector<SeamPlane> seams;
  if (p.lhs != kNoProduction) seams.push_back(seam_of(g.nonterminals[p.lhs], world));
  for (const ChildSlot& c : p.children) seams.push_back(seam_of(g.nonterminals[c.nonterminal], world.after(c.placement)));
  return seams;
}

}  // namespace

ShapeDerivation derive_shape(const ContextFreeGrammar& grammar, double eps, const ShapeDerivationOptions& options) {
  if (grammar.empty()) throw std::invalid_argument("derive_shape: the grammar has no context-free rules");
  std::vector<std::vector<std::size_t>> by_lhs(grammar.nonterminals.size());
  for (std::size_t p = 0; p < grammar.productions.size(); ++p) by_lhs[grammar.productions[p].lhs].push_back(p);

  ShapeDerivation result;
  Random random(options.seed);
  PieceCollisions collisions(options.seam_tolerance > 0 ? options.seam_tolerance : eps);
  std::size_t triangles = 0;
  std::deque<OpenSlot> open;
  auto place = [&](const ShapeProduction& p, const RigidTransform& world, int depth) {
    const TriangleMesh piece = transformed(p.terminal, world);
    collisions.add(piece);
    append_mesh(result.mesh, piece);
    if (!options.weld_seams) result.triangle_nonterminal.resize(result.mesh.triangles.size(), p.lhs);
    triangles += piece.triangles.size();
    for (const ChildSlot& c : p.children) open.push_back({c, world.after(c.placement), depth + 1});
  };
  place(grammar.axiom, RigidTransform{}, 0);

  while (!open.empty()) {
    const OpenSlot slot = open.front();
    open.pop_front();
    const std::size_t original = slot.slot.original_production;
    std::size_t chosen = original;
    const bool too_deep = slot.depth > options.max_depth;
    const bool too_big = triangles > options.max_triangles;
    result.depth_limited = result.depth_limited || too_deep;
    result.triangle_limited = result.triangle_limited || too_big;
    const std::vector<std::size_t>& candidates = by_lhs[slot.slot.nonterminal];
    if (!options.exemplar_only && !too_deep && !too_big && !candidates.empty()) {
      bool placed = false;
      for (int attempt = 0; attempt < options.retries && !placed; ++attempt) {
        const std::size_t pick = candidates[static_cast<std::size_t>(random.uniform() * static_cast<double>(candidates.size()))];
        const ShapeProduction& p = grammar.productions[pick];
        if (collisions.collides(transformed(p.terminal, slot.world), seams_of(grammar, p, slot.world))) {
          ++result.collisions_retried;
          continue;
        }
        chosen = pick;
        placed = true;
      }
      if (!placed) ++result.fallbacks;
    }
    result.productions.push_back(chosen);
    place(grammar.productions[chosen], slot.world, slot.depth);
  }
  if (options.weld_seams) resolve_t_junctions(result.mesh, 1e-6 * eps);
  return result;
}

}  // namespace dg
