#include "synthesis/variants.h"

#include "geometry/errors.h"
#include "geometry/same_surface.h"
#include "geometry/random.h"
#include "synthesis/several_grids.h"
#include "synthesis/verify.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace dg {

std::uint64_t variant_seed(std::uint64_t seed, std::uint64_t index) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (index + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

namespace {

// The counts a grid variant draws direction i of `grid` from: [ceil(count / factor), count *
// factor], at least 1 and within the grid's range.
std::pair<int, int> count_range(const GridRule& grid, std::size_t i, double factor) {
  const GridDirection& d = grid.directions[i];
  const int lo = std::max({1, lowest_count(grid, i), static_cast<int>(std::ceil(d.count / factor))});
  const int hi = std::max(lo, std::min(grid.max_count, static_cast<int>(std::floor(d.count * factor))));
  return {lo, hi};
}

}  // namespace

std::size_t largest_grid_variant_size(const ShapeGrammar& grammar, const VariantOptions& options) {
  std::vector<GridResize> largest;
  for (std::size_t g = 0; g < grammar.grids.size(); ++g) {
    largest.push_back({g, {}});
    for (std::size_t i = 0; i < grammar.grids[g].rule.directions.size(); ++i)
      largest.back().counts.push_back(count_range(grammar.grids[g].rule, i, options.range_factor).second);
  }
  return resized_model_size(grammar, largest);
}

VariantPlan plan_variant(const ShapeGrammar& grammar, std::uint64_t seed, std::uint64_t index, const VariantOptions& options) {
  VariantPlan plan;
  plan.seed = variant_seed(seed, index);
  const bool has_context_free = !grammar.context_free.empty();
  if (options.rules == VariantRules::context_free && !has_context_free)
    throw InputError("the grammar has no context-free rules (no docking site gave a production)");
  // Automatic: context-free rules when some slot has a choice (upright ones when asked), grids
  // otherwise; a grammar whose only alternatives turn pieces over gives grid variants upright.
  const bool use_context_free = options.rules == VariantRules::context_free ||
                                (options.rules == VariantRules::automatic && has_context_free &&
                                 derivation_has_choice(grammar.context_free, options.derivation));
  if (use_context_free) {
    plan.context_free = true;
    return plan;
  }
  if (grammar.grids.empty()) {
    if (!has_context_free)
      throw InputError("the grammar has no rules to vary (no grid and no context-free rule was found in the exemplar)");
    // Automatic, and the context-free rules offer no choice: every variant would be the exemplar.
    ShapeDerivationOptions free = options.derivation;
    free.up.reset();
    throw InputError(std::string("nothing in the grammar varies the exemplar: it has no grid, and no context-free slot "
                                 "has a production other than the exemplar's") +
                     (options.derivation.up && derivation_has_choice(grammar.context_free, free)
                          ? " that keeps the model upright (--orientation free lets pieces turn over)"
                          : " (productions of one shape count as one however they are triangulated)") +
                     "; --rules context-free rebuilds the exemplar");
  }
  if (!(options.range_factor >= 1.0)) throw InputError("the count range factor must be at least 1");
  Random random(plan.seed);
  // With several grids, the one resized alone when they cannot be resized together (a single
  // grid draws nothing).
  if (grammar.grids.size() > 1)
    plan.grid = std::min(grammar.grids.size() - 1, static_cast<std::size_t>(random.uniform() * static_cast<double>(grammar.grids.size())));
  for (const GridWithPieces& grid : grammar.grids) {
    std::vector<int> counts;
    const std::vector<int> exemplar_counts = dg::exemplar_counts(grid.rule);
    // Counts equal to the exemplar's in every direction rebuild the exemplar: drawn again (up to
    // 8 times, from the same stream) when the ranges allow other counts.
    bool other_counts = false;
    for (int draw = 0; draw <= 8 && (draw == 0 || (other_counts && counts == exemplar_counts)); ++draw) {
      counts.clear();
      for (std::size_t i = 0; i < grid.rule.directions.size(); ++i) {
        const auto [lo, hi] = count_range(grid.rule, i, options.range_factor);
        other_counts = other_counts || lo < hi;
        counts.push_back(lo + static_cast<int>(random.uniform() * (hi - lo + 1)));
      }
    }
    plan.grid_counts.push_back(std::move(counts));
  }
  return plan;
}

namespace {

// `dockgrammar verify` of a derived model against the grammar's exemplar at the grammar's r.
VerifyReport verify_derivation(const ShapeGrammar& grammar, const ShapeDerivation& derived) {
  Model exemplar, candidate;
  if (is_point_grammar(grammar)) {
    exemplar.cloud = grammar.exemplar_points;
    candidate.cloud = derived.points;
  } else {
    exemplar.mesh = grammar.exemplar;
    candidate.mesh = derived.mesh;
  }
  VerifyOptions options;
  options.r = grammar.r;
  return verify_models(std::move(exemplar), std::move(candidate), options);
}

}  // namespace

Variant build_variant(const ShapeGrammar& grammar, const VariantPlan& plan, const VariantOptions& options) {
  Variant variant;
  if (plan.context_free) {
    // A derivation that keeps every slot's own production rebuilds the exemplar, which is no
    // variant, and so does one whose other productions only cut the same surface otherwise (the
    // exemplar's surface within eps): up to kRedraws further seeds derived from the variant's are
    // tried for a changed one (when the grammar has a choice at all), so the result still depends
    // only on the plan.
    constexpr std::uint64_t kRedraws = 8;
    ShapeDerivationOptions derivation = options.derivation;
    bool failed = false;  // the last draw failed verify
    for (std::uint64_t draw = 0; draw <= kRedraws; ++draw) {
      derivation.seed = draw == 0 ? plan.seed : variant_seed(plan.seed, draw);
      variant.derivation = derive_shape(grammar.context_free, grammar.eps, derivation);
      variant.changed = variant.derivation.changed &&
                        (is_point_grammar(grammar) ? !same_points(variant.derivation.points, grammar.exemplar_points, grammar.eps)
                                                   : !same_surface(variant.derivation.mesh, grammar.exemplar, grammar.eps));
      variant.r_similar.reset();
      failed = false;
      if (variant.changed && options.verify) {
        const VerifyReport report = verify_derivation(grammar, variant.derivation);
        variant.r_similar = report.similarity.fraction;
        failed = !report.pass;
        if (failed) {
          ++variant.failed_verify;
          continue;
        }
      }
      if (variant.changed || (draw == 0 && !derivation_has_choice(grammar.context_free, derivation))) break;
    }
    if (failed) {
      derivation.exemplar_only = true;
      variant.derivation = derive_shape(grammar.context_free, grammar.eps, derivation);
      variant.changed = false;
      variant.r_similar.reset();
      variant.verify_fallback = true;
    }
    variant.mesh = std::move(variant.derivation.mesh);
    variant.points = std::move(variant.derivation.points);
    return variant;
  }
  std::vector<GridResize> resizes;
  for (std::size_t g = 0; g < grammar.grids.size(); ++g) resizes.push_back({g, plan.grid_counts[g]});
  auto build = [&] {
    if (is_point_grammar(grammar))
      variant.points = resize_grids_points(grammar, resizes);
    else
      variant.mesh = resize_grids(grammar, resizes);
  };
  try {
    build();
  } catch (const InputError& e) {
    if (resizes.size() < 2) throw;
    // The grids overlap: only the drawn one is resized, the others keep the exemplar's counts.
    variant.one_grid_only = e.what();
    resizes = {resizes[plan.grid]};
    build();
  }
  for (const GridWithPieces& grid : grammar.grids) variant.grid_counts.push_back(exemplar_counts(grid.rule));
  for (const GridResize& r : resizes) {
    variant.changed = variant.changed || variant.grid_counts[r.grid] != r.counts;
    variant.grid_counts[r.grid] = r.counts;
  }
  return variant;
}

}  // namespace dg
