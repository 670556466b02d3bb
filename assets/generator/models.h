#pragma once
// The individual model generators behind make_asset; each reads its parameters from a JSON
// object (see assets/README.md for every parameter, default and the meaning of each count).

#include "assets/generator/asset.h"

namespace dg::assets {

/// Fence along +x: two end posts with caps, n inner posts, two rails (1-grid of n units).
Asset make_fence(const nlohmann::json& params);
/// Wall facade facing -y: columns x rows window recesses, a ground floor with doors, a cornice.
Asset make_facade(const nlohmann::json& params);
/// The facade with pipeline damage (duplicates, slivers, unwelded vertices, a fin).
Asset make_messy_facade(const nlohmann::json& params);
/// Bookshelf: a box frame with columns x rows open cells, a back panel and a recessed plinth.
Asset make_shelf(const nlohmann::json& params);
/// Branching square pipes: every branch ends in a T joint that splits into two branches.
Asset make_pipe_tree(const nlohmann::json& params);
/// Spiral stairs: wedge steps fused to a central column, each step a screw copy of the last.
Asset make_spiral_stairs(const nlohmann::json& params);
/// Spur gear: an extruded outline with identical teeth and a round (polygonal) hole.
Asset make_gear(const nlohmann::json& params);

}  // namespace dg::assets
