#pragma once
// Random derivation of a context-free shape grammar (paper 001 §3.4.2, §4.2): starting from
// the axiom, every non-terminal slot gets a randomly chosen production of its non-terminal;
// each placed terminal is checked for collisions with everything placed before (contact at
// seams allowed). A colliding choice is retried; after `retries` failures the slot gets the
// production that rebuilds the exemplar there. Past `max_depth` or `max_triangles` every slot
// gets its exemplar production, which always ends (the exemplar's inclusion tree is finite).
// Such an exemplar production is checked too: where an earlier random choice left no room for
// it, the derivation starts over (the random stream goes on), and after `restarts` such starts
// the exemplar itself is rebuilt, so a derived model never holds colliding pieces.
// With a size range, a production is drawn only where the derivation keeps its size (surface
// area, or points) within the range: the size it would have if every open slot then took its
// exemplar production stays inside, so the finished model's does too.

#include "grammar/context_free.h"

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace dg {

struct ShapeDerivationOptions {
  std::uint64_t seed = 1;
  int retries = 10;                          ///< paper: 10
  std::size_t restarts = 10;                 ///< derivations started over before the exemplar is rebuilt
  int max_depth = 24;                        ///< nesting depth of slots
  std::size_t max_triangles = 5'000'000;     ///< placed triangles (points) before only exemplar productions are used
  bool exemplar_only = false;                ///< always take the exemplar's production (rebuilds the exemplar)
  double seam_tolerance = 0.0;               ///< model units; 0 = the grammar's eps
  bool weld_seams = true;                    ///< false: pieces stay separate (for pictures)
  /// Upright derivation: when set (a unit model axis), a production is chosen only where it keeps
  /// this axis pointing as it did in the exemplar (rotations about it stay allowed), so a window
  /// is never placed lying on its side. Needs every production's source_frame.
  std::optional<Vec3> up;
  /// Size range of the derived model as fractions of the exemplar's (surface area; the number of
  /// points for a point-cloud grammar): min_size <= 1 <= max_size. Productions that would leave
  /// it are not drawn. The default keeps at least half the exemplar (without it, a cap that can
  /// take the place of a whole subtree makes most variants stubs) and sets no upper limit.
  double min_size = 0.5;
  double max_size = std::numeric_limits<double>::infinity();
};

struct ShapeDerivation {
  TriangleMesh mesh;                        ///< welded at the seams, flat faces split by seams merged
  PointCloud points;                        ///< a point-cloud grammar's result (then `mesh` is empty)
  std::vector<std::size_t> productions;     ///< applied productions (indices), in placement order
  bool changed = false;                     ///< some slot took another production than the exemplar's
  std::size_t collisions_retried = 0;       ///< random choices rejected for colliding
  std::size_t fallbacks = 0;                ///< slots that got the exemplar production after `retries` failures
  /// Derivations started over because an exemplar production found no room; options.restarts + 1
  /// when all of them failed and the result is the exemplar rebuilt.
  std::size_t restarts = 0;
  bool depth_limited = false;               ///< max_depth was reached somewhere
  bool triangle_limited = false;            ///< max_triangles was reached
  /// Without welding: the non-terminal whose production placed each triangle (kNoProduction
  /// for the axiom's terminal). Empty when the seams were welded.
  std::vector<std::size_t> triangle_nonterminal;
  /// The same for each point of a point-cloud grammar's result (points are never welded).
  std::vector<std::size_t> point_nonterminal;
};

/// Whether some slot of the exemplar's own derivation (within max_depth) may take a production
/// other than the exemplar's there (with `options.up`: an upright one). Without such a slot
/// every derivation rebuilds the exemplar.
bool derivation_has_choice(const ContextFreeGrammar& grammar, const ShapeDerivationOptions& options);

/// Derives one model from `grammar` (must not be empty). `eps` is the grammar's voxel size:
/// seams of different placed pieces are welded within seam_weld_tolerance (grammar/context_free.h),
/// vertices of one piece only within 1e-4 eps (see resolve_t_junctions). Deterministic for a
/// given seed. A point-cloud grammar (ContextFreeGrammar::of_points) gives `points`: pieces
/// collide when their points share a cube of edge eps away from their seams (seam tolerance 2 eps
/// unless set), and max_triangles counts points.
ShapeDerivation derive_shape(const ContextFreeGrammar& grammar, double eps, const ShapeDerivationOptions& options);

}  // namespace dg
