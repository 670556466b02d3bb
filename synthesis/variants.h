#pragma once
// Random variants of a grammar. Version-1 grammars hold grid rules only, so a variant draws
// new counts for every grid direction; variant i depends only on (grammar, seed, i).

#include "grammar/grammar_file.h"

#include <cstdint>
#include <vector>

namespace dg {

struct VariantOptions {
  /// Counts are drawn uniformly from [ceil(count / range_factor), count * range_factor] (at
  /// least 1, within the grid's count range), count = the exemplar's count.
  double range_factor = 2.0;
};

/// The random choices of one variant.
struct VariantPlan {
  std::uint64_t seed = 0;                      ///< the variant's own seed (derived from seed and index)
  std::vector<std::vector<int>> grid_counts;   ///< per grid, per direction
};

/// Seed of variant `index` of a batch started with `seed` (SplitMix64 of both).
std::uint64_t variant_seed(std::uint64_t seed, std::uint64_t index);

/// Draws the counts of variant `index`. Throws InputError when the grammar has nothing to vary.
VariantPlan plan_variant(const ShapeGrammar& grammar, std::uint64_t seed, std::uint64_t index, const VariantOptions& options = {});

/// Builds the mesh of a planned variant (grids resized; a grammar with one grid only).
TriangleMesh build_variant(const ShapeGrammar& grammar, const VariantPlan& plan);

}  // namespace dg
