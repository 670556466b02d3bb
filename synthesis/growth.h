#pragma once
// Guided growth (Beneš et al. 2011 §3.3): every seed's Open L-system string is rewritten in
// parallel, one step for all at a time; between steps the turtle interprets each string from
// its seed (growth_string.h: only the parts that can still change cost work) and the guide's
// environment answers the fresh query modules (growth_queries.h). Tokens (§3.3.2): a link
// query that selects a link reserves a free token for its branch and hides the link from other
// branches; a ?X of the branch that crosses the link's edge and is rewritten into a drawn
// segment uses it and starts a seed on the target edge (parameters of the ?X travel with it);
// when the branch has no module left that can act, the token is freed. Growth ends when no
// string rewrites and no seed waits; tokens bound it.

#include "synthesis/growth_scene.h"
#include "synthesis/path2d.h"
#include "synthesis/segment_grid.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dg {

/// A seed a guide received through a link: which link, where on the start edge (parameter t),
/// the values it carries and the step it arrived in.
struct ReceivedSeed {
  std::size_t link = 0;
  double t = 0;
  std::vector<double> values;
  int step = 0;

  friend bool operator==(const ReceivedSeed&, const ReceivedSeed&) = default;
};

/// What grew in one guide: the kept elements (centre inside the guide): segments with their
/// ids and motif copies; the seeds it received; how many seeds ran.
struct GuideGrowth {
  std::vector<GridSegment> segments;
  std::vector<Path2d> motifs;
  std::vector<ReceivedSeed> received;
  std::size_t seeds = 0;
};

/// Token states of one link after growth (reserved is 0 once growth has ended).
struct TokenState {
  int free = 0;
  int reserved = 0;
  int used = 0;
};

/// The grown scene.
struct GrowthResult {
  std::vector<GuideGrowth> guides;  ///< one per scene guide
  std::vector<TokenState> tokens;   ///< one per scene link
  int steps = 0;                    ///< parallel steps until growth ended
  std::size_t regrown_guides = 0;   ///< guides grown by this run (all, or the changed ones and their dependents)

  /// Kept elements (segments and motifs) of all guides.
  std::size_t elements() const;
};

/// Options of a growth run.
struct GrowthOptions {
  std::uint64_t seed = 1;  ///< seeds the stochastic productions (per guide)
};

/// Grows the whole scene. Throws InputError for a bad scene (see scene checks in
/// check_growth_scene) and LimitError when a limit of scene.limits is reached.
GrowthResult grow(const GrowthScene& scene, const GrowthOptions& options = {});

/// The guides that must regrow when `changed` guides change: those and every guide reachable
/// from them through links, in index order.
std::vector<std::size_t> dependent_guides(const GrowthScene& scene, const std::vector<std::size_t>& changed);

/// Incremental update (§3.3.4): regrows the changed guides and their dependents from their
/// explicit seeds and the seeds `previous` recorded from guides that stay; the other guides
/// and the tokens of their links are copied from `previous`. Gives the same result as grow()
/// on the edited scene.
GrowthResult regrow(const GrowthScene& scene, const GrowthResult& previous, const std::vector<std::size_t>& changed,
                    const GrowthOptions& options = {});

/// Checks what growth relies on and throws InputError naming the guide or link: polygons with
/// at least 3 vertices that do not self-intersect, indices in range, tokens >= 0.
void check_growth_scene(const GrowthScene& scene);

}  // namespace dg
