#pragma once
// Random derivation of a context-free shape grammar (paper 001 §3.4.2, §4.2): starting from
// the axiom, every non-terminal slot gets a randomly chosen production of its non-terminal;
// each placed terminal is checked for collisions with everything placed before (contact at
// seams allowed). A colliding choice is retried; after `retries` failures the slot gets the
// production that rebuilds the exemplar there. Past `max_depth` or `max_triangles` every slot
// gets its exemplar production, which always ends (the exemplar's inclusion tree is finite).

#include "grammar/context_free.h"

#include <cstdint>
#include <string>
#include <vector>

namespace dg {

struct ShapeDerivationOptions {
  std::uint64_t seed = 1;
  int retries = 10;                          ///< paper: 10
  int max_depth = 24;                        ///< nesting depth of slots
  std::size_t max_triangles = 5'000'000;     ///< placed triangles before only exemplar productions are used
  bool exemplar_only = false;                ///< always take the exemplar's production (rebuilds the exemplar)
  double seam_tolerance = 0.0;               ///< model units; 0 = the grammar's eps
  bool weld_seams = true;                    ///< false: pieces stay separate (for pictures)
};

struct ShapeDerivation {
  TriangleMesh mesh;                        ///< welded at the seams
  std::vector<std::size_t> productions;     ///< applied productions (indices), in placement order
  std::size_t collisions_retried = 0;       ///< random choices rejected for colliding
  std::size_t fallbacks = 0;                ///< slots that got the exemplar production after `retries` failures
  bool depth_limited = false;               ///< max_depth was reached somewhere
  bool triangle_limited = false;            ///< max_triangles was reached
  /// Without welding: the non-terminal whose production placed each triangle (kNoProduction
  /// for the axiom's terminal). Empty when the seams were welded.
  std::vector<std::size_t> triangle_nonterminal;
};

/// Derives one model from `grammar` (must not be empty). `eps` is the grammar's voxel size:
/// seams are welded within 1e-6 eps. Deterministic for a given seed.
ShapeDerivation derive_shape(const ContextFreeGrammar& grammar, double eps, const ShapeDerivationOptions& options);

}  // namespace dg
