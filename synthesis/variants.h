#pragma once
// Random variants of a grammar: a random derivation of its context-free rules, or new random
// counts for its grids. Variant i depends only on (grammar, seed, i).

#include "grammar/grammar_file.h"
#include "synthesis/shape_derivation.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace dg {

/// Which rules make variants. automatic: context-free rules when the grammar has them and some
/// slot has a choice under the derivation options (see derivation_has_choice), else the grid;
/// neither is an input error (every variant would be the exemplar).
enum class VariantRules { automatic, grid, context_free };

struct VariantOptions {
  VariantRules rules = VariantRules::automatic;
  /// Grid variants: counts are drawn uniformly from [ceil(count / range_factor),
  /// count * range_factor] (at least 1, within the grid's count range), count = the exemplar's;
  /// a draw of the exemplar's counts in every direction is drawn again (up to 8 times).
  double range_factor = 2.0;
  /// Context-free variants: retries, limits (the seed is set per variant).
  ShapeDerivationOptions derivation;
  /// Context-free variants: check every changed draw as `dockgrammar verify` does (closed and
  /// free of self-intersections where the exemplar is, r-similar at the grammar's r) and draw
  /// again when it fails (with the redraws of unchanged draws, up to 8 in all); when every draw
  /// failed, the variant is the exemplar rebuilt. Collision checks alone let pieces come within
  /// r of each other without touching, which can make neighbourhoods the exemplar lacks.
  bool verify = false;
};

/// The random choices of one variant.
struct VariantPlan {
  std::uint64_t seed = 0;                      ///< the variant's own seed (derived from seed and index)
  bool context_free = false;                   ///< derived from the context-free rules
  std::vector<std::vector<int>> grid_counts;   ///< grid variants: per grid, per direction
  /// Grid variants with several grids: the one grid resized when they cannot be resized together
  /// (see resize_grids), drawn at random; the others then keep the exemplar's counts.
  std::size_t grid = 0;
};

/// A built variant.
struct Variant {
  TriangleMesh mesh;   ///< empty for a point-cloud grammar
  PointCloud points;   ///< a point-cloud grammar's variant
  ShapeDerivation derivation;  ///< context-free variants: what was applied (its mesh is moved to `mesh`)
  /// It differs from the exemplar: other grid counts, or a derivation whose surface is not the
  /// exemplar's (see build_variant).
  bool changed = false;
  /// Grid variants: the counts built, per grid (the plan's, or, when its grids cannot be resized
  /// together, the plan's for its drawn grid and the exemplar's for the others).
  std::vector<std::vector<int>> grid_counts;
  /// Why the grids were not resized together (resize_grids' error); empty when they were.
  std::string one_grid_only;
  /// With VariantOptions::verify (context-free variants): draws that failed the check, the
  /// r-similar fraction of the kept draw when it was checked (a draw with the exemplar's surface
  /// is not), and whether every draw failed so the result is the exemplar rebuilt.
  std::size_t failed_verify = 0;
  std::optional<double> r_similar;
  bool verify_fallback = false;
};

/// Seed of variant `index` of a batch started with `seed` (SplitMix64 of both).
std::uint64_t variant_seed(std::uint64_t seed, std::uint64_t index);

/// The most triangles (points, for a point-cloud grammar) a grid variant can place before
/// welding: the exemplar's, plus what each grid adds at the largest counts options.range_factor
/// lets it draw in every direction (resized_size), so a batch can be refused before it starts.
std::size_t largest_grid_variant_size(const ShapeGrammar& grammar, const VariantOptions& options);

/// Plans variant `index`. Throws InputError when the grammar has no rules of the requested kind.
VariantPlan plan_variant(const ShapeGrammar& grammar, std::uint64_t seed, std::uint64_t index, const VariantOptions& options = {});

/// Builds the mesh (or, for a point-cloud grammar, the points) of a planned variant: all grids
/// at the plan's counts (resize_grids), or only the plan's drawn grid when they cannot be resized
/// together. A
/// context-free derivation that happens to keep every slot's exemplar production, or whose other
/// productions give the exemplar's surface again (within eps, see same_surface: another
/// decomposition of the same parts), is drawn again (up to 8 times, with seeds derived from the
/// plan's), so variants differ from the exemplar whenever the grammar offers a choice; `changed`
/// says whether the result does. With options.verify, draws that fail verify are drawn again too.
Variant build_variant(const ShapeGrammar& grammar, const VariantPlan& plan, const VariantOptions& options = {});

}  // namespace dg
