#include "synthesis/several_grids.h"

#include "geometry/errors.h"
#include "grammar/grid_cut.h"
#include "synthesis/grid_resize.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <numeric>
#include <optional>
#include <utility>

namespace dg {
namespace {

bool keeps_parts_whole(const GridRule& grid) {
  return std::any_of(grid.directions.begin(), grid.directions.end(),
                     [](const GridDirection& d) { return !d.whole_in_head.empty() || !d.whole_in_tail.empty(); });
}

bool changes_counts(const GridRule& grid, const std::vector<int>& counts) {
  for (std::size_t i = 0; i < grid.directions.size() && i < counts.size(); ++i)
    if (counts[i] != grid.directions[i].count) return true;
  return counts.size() != grid.directions.size();  // resize_grid reports the mismatch
}

// The directions of `grid` whose count `counts` changes, as a grid of their own, with their
// counts: along a direction kept at the exemplar's count every piece stays where it is, so a
// resize that changes only some directions is the resize of this grid (its slabs along the
// changed directions are copies of each other as wholes).
std::pair<GridRule, std::vector<int>> changing_directions(const GridRule& grid, const std::vector<int>& counts) {
  GridRule changing = grid;
  changing.directions.clear();
  std::vector<int> changing_counts;
  for (std::size_t i = 0; i < grid.directions.size(); ++i)
    if (counts[i] != grid.directions[i].count) {
      changing.directions.push_back(grid.directions[i]);
      changing_counts.push_back(counts[i]);
    }
  return {std::move(changing), std::move(changing_counts)};
}

// Positions a resize of `grid` to `counts` moves or adds: the vertices (points) of its pieces
// that are not head pieces in every direction whose count changes, where the exemplar's counts
// and `counts` put them.
std::vector<Vec3> changed_positions(const GridRule& grid, const std::vector<GridPiece>& pieces, const std::vector<int>& counts) {
  const std::vector<int> exemplar_counts = dg::exemplar_counts(grid);
  std::vector<Vec3> positions;
  for (const GridPiece& piece : pieces) {
    bool stays = true;
    for (std::size_t i = 0; i < counts.size(); ++i) stays = stays && (counts[i] == exemplar_counts[i] || piece.classes[i] == 0);
    if (stays) continue;
    for (const std::vector<int>* c : {&std::as_const(exemplar_counts), &counts})
      for (const RigidTransform& placement : piece_placements(grid, piece, *c)) {
        for (const Vec3& p : piece.mesh.positions) positions.push_back(placement.apply(p));
        for (const Vec3& p : piece.points.positions) positions.push_back(placement.apply(p));
      }
  }
  return positions;
}

// The piece classes of `grid` (0 head, 1 unit, 2 tail, -1 a copy of the unit, per direction)
// that all of `positions` share, or nothing when they do not share one.
std::optional<std::vector<int>> shared_classes(const GridRule& grid, const std::vector<Vec3>& positions) {
  std::optional<std::vector<int>> shared;
  for (const Vec3& p : positions) {
    std::vector<int> classes;
    for (const GridDirection& d : grid.directions) classes.push_back(slab_class(slab_of_point(d, p), d));
    if (!shared) shared = classes;
    if (*shared != classes) return std::nullopt;
  }
  return shared;
}

// How the positions changed so far meet `grid`, resized next: nothing when they do not all lie
// in one head or tail piece of it, else whether that piece is a tail along some direction (its
// resize moves them along, so grids after it need not judge them again).
std::optional<bool> moved_with_tail(const GridRule& grid, const std::vector<Vec3>& changed) {
  const std::optional<std::vector<int>> classes = shared_classes(grid, changed);
  if (!classes || std::any_of(classes->begin(), classes->end(), [](int c) { return c != 0 && c != 2; })) return std::nullopt;
  return std::any_of(classes->begin(), classes->end(), [](int c) { return c != 0; });
}

// Most resizes whose orders are tried; beyond, grammar order is kept.
constexpr std::size_t kOrdersTried = 5;

// Whether resizing in `order` keeps what each resize changes (`changes`, per grid, where the
// exemplar's pieces put them) in one head or tail piece of every grid resized after it; a tail
// moves what it holds, which then needs no further check (as resize_in_order judges it).
bool stays_in_stored_pieces(const ShapeGrammar& grammar, const std::vector<GridResize>& order,
                            const std::vector<std::vector<Vec3>>& changes) {
  std::vector<Vec3> changed;
  for (std::size_t step = 0; step < order.size(); ++step) {
    const GridRule grid = changing_directions(grammar.grids[order[step].grid].rule, order[step].counts).first;
    if (step > 0 && !changed.empty()) {
      const std::optional<bool> with_tail = moved_with_tail(grid, changed);
      if (!with_tail) return false;
      if (*with_tail) changed.clear();
    }
    changed.insert(changed.end(), changes[step].begin(), changes[step].end());
  }
  return true;
}

// `resizes` (the one keeping parts whole first, then grammar order) in the first order that
// stays_in_stored_pieces, or as given when none does (resize_in_order then names the overlap).
std::vector<GridResize> feasible_order(const ShapeGrammar& grammar, std::vector<GridResize> resizes) {
  if (resizes.size() < 2 || resizes.size() > kOrdersTried) return resizes;
  const bool whole_first = keeps_parts_whole(grammar.grids[resizes.front().grid].rule);
  std::vector<std::vector<Vec3>> changes;
  for (const GridResize& r : resizes) {
    const GridWithPieces& grid = grammar.grids[r.grid];
    changes.push_back(changed_positions(grid.rule, grid.pieces, r.counts));
  }
  std::vector<std::size_t> permutation(resizes.size());
  std::iota(permutation.begin(), permutation.end(), std::size_t{0});
  do {
    if (whole_first && permutation.front() != 0) continue;
    std::vector<GridResize> order;
    std::vector<std::vector<Vec3>> ordered_changes;
    for (std::size_t i : permutation) order.push_back(resizes[i]), ordered_changes.push_back(changes[i]);
    if (stays_in_stored_pieces(grammar, order, ordered_changes)) return order;
  } while (std::next_permutation(permutation.begin(), permutation.end()));
  return resizes;
}

// The resizes in the order they are applied: the one grid that keeps separate parts whole first
// (its parts are named by the exemplar's triangles, so only the exemplar's pieces hold them),
// then the first order (by grammar order) in which, judged on the exemplar's pieces, what each
// resize changes lies in one head or tail piece of every grid resized after it; grids keeping
// their exemplar's counts are left out unless all do.
std::vector<GridResize> resize_order(const ShapeGrammar& grammar, std::vector<GridResize> resizes) {
  for (std::size_t a = 0; a < resizes.size(); ++a) {
    if (resizes[a].grid >= grammar.grids.size()) throw InputError(fmt::format("no grid {}", resizes[a].grid + 1));
    for (std::size_t b = 0; b < a; ++b)
      if (resizes[a].grid == resizes[b].grid)
        throw InputError(fmt::format("grid {} is given twice", grammar.grids[resizes[a].grid].rule.name));
  }
  if (resizes.empty()) throw InputError("no grid to resize");
  std::vector<GridResize> changing;
  for (const GridResize& r : resizes) check_counts(grammar.grids[r.grid].rule, r.counts);
  for (const GridResize& r : resizes)
    if (changes_counts(grammar.grids[r.grid].rule, r.counts)) changing.push_back(r);
  if (changing.empty()) changing.push_back(resizes.front());
  std::stable_sort(changing.begin(), changing.end(), [&](const GridResize& a, const GridResize& b) {
    const bool whole_a = keeps_parts_whole(grammar.grids[a.grid].rule), whole_b = keeps_parts_whole(grammar.grids[b.grid].rule);
    return whole_a != whole_b ? whole_a : a.grid < b.grid;
  });
  if (changing.size() > 1 && keeps_parts_whole(grammar.grids[changing[1].grid].rule))
    throw InputError(fmt::format("grids {} and {} both keep separate parts whole: resize one, analyze the result, then "
                                 "resize the other",
                                 grammar.grids[changing[0].grid].rule.name, grammar.grids[changing[1].grid].rule.name));
  for (const GridResize& a : changing)
    for (const GridResize& b : changing)
      if (const std::optional<GroupedUnits> grouped = grouped_units(grammar.grids[a.grid].rule, grammar.grids[b.grid].rule))
        throw InputError(fmt::format("{} groups the units of {} ({} of them along direction {} make one): they are "
                                     "two ways to resize the same part of the model; resize one of them",
                                     grammar.grids[a.grid].rule.name, grammar.grids[b.grid].rule.name, grouped->factor,
                                     grouped->direction + 1));
  return feasible_order(grammar, std::move(changing));
}

// Applies the resizes in order: `resize` builds a result from a grid's pieces, `recut` cuts a
// result into a grid's pieces.
template <typename Geometry>
Geometry resize_in_order(const ShapeGrammar& grammar, const std::vector<GridResize>& order,
                         const std::function<Geometry(const GridRule&, const std::vector<GridPiece>&, const std::vector<int>&)>& resize,
                         const std::function<std::vector<GridPiece>(const Geometry&, const GridRule&)>& recut) {
  Geometry result;
  std::vector<Vec3> changed;  // positions the resizes so far moved or added, where they lie in `result`
  std::string changed_by;     // the grids that changed them
  for (std::size_t step = 0; step < order.size(); ++step) {
    const GridWithPieces& grid = grammar.grids[order[step].grid];
    // The first resize uses the stored pieces; later ones cut the result along the planes of the
    // directions they change only.
    const auto [rule, counts] = step == 0 ? std::pair{grid.rule, order[step].counts} : changing_directions(grid.rule, order[step].counts);
    std::vector<GridPiece> recut_pieces;
    if (step > 0 && !changed.empty()) {
      const std::optional<bool> with_tail = moved_with_tail(rule, changed);
      if (!with_tail)
        throw InputError(fmt::format("grids {} and {} overlap: resizing {} changes the model inside more than one piece, "
                                     "or inside the repeated units, of {}; resize one, analyze the result, then resize "
                                     "the other",
                                     changed_by, grid.rule.name, changed_by, grid.rule.name));
      if (*with_tail) changed.clear();
    }
    if (step > 0) recut_pieces = recut(result, rule);
    const std::vector<GridPiece>& pieces = step == 0 ? grid.pieces : recut_pieces;
    result = resize(rule, pieces, counts);
    const std::vector<Vec3> moved = changed_positions(rule, pieces, counts);
    changed.insert(changed.end(), moved.begin(), moved.end());
    changed_by += (changed_by.empty() ? "" : " and ") + grid.rule.name;
  }
  return result;
}

}  // namespace

TriangleMesh resize_grids(const ShapeGrammar& grammar, const std::vector<GridResize>& resizes) {
  return resize_in_order<TriangleMesh>(
      grammar, resize_order(grammar, resizes),
      [&](const GridRule& rule, const std::vector<GridPiece>& pieces, const std::vector<int>& counts) {
        return resize_grid(rule, pieces, counts, grammar.eps);
      },
      [&](const TriangleMesh& mesh, const GridRule& rule) { return cut_grid_pieces(mesh, rule, grammar.eps); });
}

std::size_t resized_model_size(const ShapeGrammar& grammar, const std::vector<GridResize>& resizes) {
  double size = static_cast<double>(is_point_grammar(grammar) ? grammar.exemplar_points.positions.size()
                                                                : grammar.exemplar.triangles.size());
  for (const GridResize& resize : resizes) {
    const GridWithPieces& grid = grammar.grids[resize.grid];
    size += static_cast<double>(resized_size(grid.rule, grid.pieces, resize.counts)) -
            static_cast<double>(resized_size(grid.rule, grid.pieces, exemplar_counts(grid.rule)));
  }
  return static_cast<std::size_t>(std::max(0.0, size));
}

PointCloud resize_grids_points(const ShapeGrammar& grammar, const std::vector<GridResize>& resizes) {
  return resize_in_order<PointCloud>(grammar, resize_order(grammar, resizes), resize_grid_points, cut_grid_points);
}

}  // namespace dg
