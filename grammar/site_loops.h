#pragma once
// How a docker and the rest of the model join the loops of a docking site: a site can be
// several bands (loops around the stems of a tree, the bars of a railing), and a docker that
// joins them, put where another docker only caps each one, leaves the model in separate parts.

#include "geometry/rigid_transform.h"
#include "geometry/voxel_surface.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace dg {

/// The loops of a docking site (its connected parts, 26-adjacency) and what joins them.
struct SiteLoops {
  std::vector<std::int32_t> loop_of;           ///< per site cell, in the site's order: its loop
  std::vector<std::uint32_t> representative;   ///< per loop: one of its cells
  std::vector<std::uint32_t> rest_part;        ///< per loop: the connected part of the model outside the docker holding it
  std::vector<std::vector<std::uint32_t>> docker_parts;  ///< per connected part of the docker: the loops it touches
};

/// The loops of `site` around `docker` (both ascending cell lists) and the parts that join them.
SiteLoops site_loops(const VoxelSurface& surface, const std::vector<std::uint32_t>& site, const std::vector<std::uint32_t>& docker);

/// Into how many groups the loops of location `at` fall, joined through the rest of the model
/// at `at` and through each connected part of the docker of location `from`, whose loops
/// `from_to_at` carries onto those of `at` (the identity with `from` = `at`: the exemplar as it
/// is; then never nothing). Nothing when a loop of `from` lands on no loop of `at`.
std::optional<std::size_t> joined_loop_groups(const VoxelSurface& surface, const std::vector<std::uint32_t>& at_site,
                                              const SiteLoops& at, const SiteLoops& from, const RigidTransform& from_to_at);

}  // namespace dg
