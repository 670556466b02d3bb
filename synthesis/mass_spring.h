#pragma once
// Mass-spring editing of guides (Beneš et al. 2011 §4.2): guide vertices are particles (guides
// snapped together share the particles of coincident vertices), guide edges and diagonals are
// springs that keep each guide's shape, and stiff springs between guides (across every link and
// as the scene lists) keep links rigid. Dragging a particle moves the others to the spring
// system's rest.

#include "synthesis/growth_scene.h"

#include <cstddef>
#include <vector>

namespace dg {

/// Drags vertex `vertex` of guide `guide` to `target` (drawing units) and moves every other
/// non-pinned vertex of the scene by relaxing the springs (rest lengths: the lengths before the
/// drag; Gauss-Seidel projection, scene.springs.iterations sweeps, stiffness relative to the
/// stiffest spring). Explicit seeds follow the displacement of their guide's nearest vertex.
/// Returns the guides whose vertices moved, in index order.
std::vector<std::size_t> drag_guide_vertex(GrowthScene& scene, std::size_t guide, std::size_t vertex, const Vec2& target);

}  // namespace dg
