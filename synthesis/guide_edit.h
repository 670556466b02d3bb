#pragma once
// Editing guides (Beneš et al. 2011 §4.1-4.2): translate, rotate, scale, snap one guide onto
// another, or drag a vertex through the mass-spring system.

#include "synthesis/growth_scene.h"

#include <cstddef>
#include <vector>

namespace dg {

/// Applies `edit` to `scene` (explicit seeds move with their guide) and returns the guides
/// whose polygons changed, in index order. Rotate and scale act about the guide's vertex
/// centroid. Snap moves `edit.guide` rigidly so that its edge `edit.edge` lies on edge
/// `edit.target_edge` of `edit.target` with opposite orientation, then puts the two vertices
/// exactly on the target's (the guides then share them, also for the mass-spring system).
/// Throws InputError for a guide, vertex or edge out of range.
std::vector<std::size_t> apply_guide_edit(GrowthScene& scene, const GuideEdit& edit);

}  // namespace dg
