#pragma once
// Context-free shape grammar from docking sites (paper 001 §3.4.2).
//
// Every docking site location in the exemplar (primary and secondary sites alike) is a node
// with its band and docker. Nodes related by the motion of a site (or found at the same place
// twice) share one non-terminal; each node keeps the rigid motion `frame` that maps the
// non-terminal's own frame (that of its first node) onto the node. Nodes form an inclusion
// tree (a node is a child of the smallest docker holding its band and docker). For each node,
// randomly sampled maximal independent sets of its non-conflicting children (sites sharing
// cells or dockers overlapping conflict), with one hierarchy level unfolded (a child left out
// for a conflict lets its own children in; grammar/site_conflicts.h), give productions
//     node's non-terminal -> terminal remainder + child non-terminals,
// stored in the non-terminal's frame; the whole model is the axiom.
//
// Geometry is cut out of the original triangles along one seam per non-terminal, built from the
// band of its first node and mapped by each node's frame: a plane when the band lies flat,
// else the voxel faces between the band's cells next to the docker and the cells beyond them.
// A docker cut at one node then fits exactly into the seam of any other node of the same
// non-terminal; nodes where it does not (the seam curves differ) are dropped, and so are sites
// that slide along themselves (slippage). A point cloud's pieces are sets of its points split by
// the same seams (points have no seam curve to fit).

#include "geometry/mesh.h"
#include "geometry/prepared_model.h"
#include "geometry/progress.h"
#include "geometry/rigid_transform.h"
#include "grammar/docking_sites.h"
#include "grammar/seam_surface.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace dg {

inline constexpr std::size_t kNoProduction = std::numeric_limits<std::size_t>::max();

/// A non-terminal: a docking site shape with the seam its dockers are cut along (in its own
/// frame).
struct ShapeNonterminal {
  std::string name;
  SeamSurface seam;
  std::size_t sites = 0;  ///< exemplar locations of this shape
  /// Largest distance (model units) between the seam curve of a location and that of its first
  /// location, in this frame: how exactly the locations repeat (see seam_misfit).
  double seam_misfit = 0.0;
};

/// A non-terminal occurrence on the right-hand side of a production.
struct ChildSlot {
  std::size_t nonterminal = 0;
  RigidTransform placement;  ///< from the child's frame to the parent production's frame
  /// The production that rebuilds the exemplar at this place (fallback after collisions).
  std::size_t original_production = kNoProduction;
};

/// lhs -> terminal + children. The axiom has lhs == kNoProduction.
struct ShapeProduction {
  std::size_t lhs = kNoProduction;
  TriangleMesh terminal;  ///< in the lhs frame (model frame for the axiom); empty for a point cloud
  PointCloud terminal_points;  ///< a point-cloud exemplar's terminal: its points (with normals when it had them), same frame
  /// A point cloud's terminal as indices of the exemplar's points: terminal_points is them moved
  /// by source_frame^-1 (the grammar file stores these instead of the points). Empty for meshes.
  std::vector<std::uint32_t> terminal_source_points;
  std::vector<ChildSlot> children;
  std::size_t source_site = 0;  ///< exemplar location it was cut from (report only)
  /// From the lhs frame to the model at that location (identity for the axiom); tells how the
  /// piece was oriented in the exemplar. Absent in grammar files written before it existed.
  std::optional<RigidTransform> source_frame;
};

struct ContextFreeGrammar {
  std::vector<ShapeNonterminal> nonterminals;
  std::vector<ShapeProduction> productions;  ///< all with lhs set, grouped by nothing in particular
  ShapeProduction axiom;
  bool empty() const { return nonterminals.empty(); }
  /// True when the terminals are points (the grammar of a point cloud).
  bool of_points() const {
    return !axiom.terminal_points.positions.empty() ||
           std::any_of(productions.begin(), productions.end(), [](const ShapeProduction& p) { return !p.terminal_points.positions.empty(); });
  }
};

/// How close (model units) the seam vertices of pieces derived from `grammar` are welded: twice
/// the largest seam misfit of its non-terminals (a piece cut at one location placed at another
/// differs from both by at most that), at least kSeamWeldFloorFraction of `eps`.
double seam_weld_tolerance(const ContextFreeGrammar& grammar, double eps);

struct ContextFreeOptions {
  int independent_set_trials = 10;  ///< random maximal independent sets per node (paper: 10)
  std::uint64_t seed = 1;           ///< seeds the independent-set sampling
  std::size_t max_nodes = 256;      ///< docking site locations kept (largest dockers first)
};

struct ContextFreeStats {
  std::size_t sites_used = 0;        ///< docking sites that entered the grammar
  std::size_t sites_slippable = 0;   ///< dropped: the band slides along itself
  std::size_t sites_without_fit = 0;  ///< dropped: the docker cut at one location does not fit the other
  /// Dropped: the image of the site also runs where nothing is cut off (DockingSite::stray_seam),
  /// so the seam at the second location would not be the first's, moved.
  std::size_t sites_stray_seam = 0;
  std::size_t nodes = 0;             ///< distinct site locations
  /// Pairs of locations a site relates that do not share a non-terminal: the docker of one, put
  /// in place of the other's, would leave that site's loops in more groups (the model in more
  /// parts) than its own docker does (grammar/site_loops).
  std::size_t locations_kept_apart = 0;
  /// Kept locations whose frame was aligned on the seam of their non-terminal's first location
  /// (placed a little off the motion relating them), and the farthest such a seam moved (model
  /// units).
  std::size_t locations_aligned = 0;
  double largest_alignment = 0.0;
  /// Productions dropped because their piece holds a triangle cleaning drops (closed exemplars:
  /// it would open a hole), and whether the axiom did too (then the grammar is left empty).
  std::size_t productions_with_holes = 0;
  bool axiom_with_holes = false;
  /// Productions dropped because putting them at another location of their non-terminal only
  /// moves the whole exemplar (every location has the same rest of the model around it, moved).
  std::size_t productions_moving_the_model = 0;
  /// Non-terminals dropped because no derivation reaches them from the axiom (their locations
  /// lie in alternatives that the axiom's independent set of sites left out).
  std::size_t unreachable_nonterminals = 0;
};

/// Builds the context-free grammar of a prepared model from its docking sites. Deterministic for
/// a given seed. A mesh's pieces are cut from its triangles along the seams; a point cloud's are
/// its points, each going to the dockers whose cells hold it (in a band cell, on the docker side
/// of the seam), so every location fits (seam misfit 0). `progress` hears stage "context-free
/// rules" with the fraction done (for meshes most of the time goes into cutting the exemplar
/// along the seams of every site location).
ContextFreeGrammar build_context_free_grammar(const PreparedModel& prepared, const DockingSiteResult& sites,
                                              const ContextFreeOptions& options, ContextFreeStats* stats = nullptr,
                                              const ProgressCallback& progress = {});

}  // namespace dg
