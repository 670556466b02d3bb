#include "synthesis/shape_derivation.h"

#include "geometry/errors.h"
#include "geometry/flat_faces.h"
#include "geometry/submesh.h"
#include "geometry/t_junctions.h"
#include "geometry/random.h"
#include "grammar/seam_curve.h"
#include "synthesis/piece_collision.h"
#include "synthesis/point_collision.h"

#include <algorithm>
#include <deque>
#include <functional>
#include <optional>
#include <stdexcept>
#include <type_traits>

namespace dg {
namespace {

// How far (unit vectors) the up axis of a chosen piece may be from the exemplar's: 1e-3 rad.
constexpr double kUprightTolerance = 1e-3;

struct OpenSlot {
  ChildSlot slot;
  RigidTransform world;  // child frame -> model
  int depth = 1;
};

// Contact test for a production placed with `world`: points within `tolerance` of its own seam
// or of the seams of its slots (each in its non-terminal's frame).
SeamContact contact_of(const ContextFreeGrammar& g, const ShapeProduction& p, const RigidTransform& world, double tolerance) {
  std::vector<std::pair<const SeamSurface*, RigidTransform>> seams;  // seam, model -> seam frame
  if (p.lhs != kNoProduction) seams.push_back({&g.nonterminals[p.lhs].seam, world.inverse()});
  for (const ChildSlot& c : p.children) seams.push_back({&g.nonterminals[c.nonterminal].seam, world.after(c.placement).inverse()});
  return [seams = std::move(seams), tolerance](const Vec3& x) {
    return std::any_of(seams.begin(), seams.end(), [&](const auto& s) { return s.first->near(s.second.apply(x), tolerance); });
  };
}

// The productions a slot may take: those of its non-terminal, and with an up axis only those
// that keep it pointing as the piece stood in the exemplar.
class Candidates {
 public:
  Candidates(const ContextFreeGrammar& grammar, const std::optional<Vec3>& up) : by_lhs_(grammar.nonterminals.size()), up_(up) {
    for (std::size_t p = 0; p < grammar.productions.size(); ++p) by_lhs_[grammar.productions[p].lhs].push_back(p);
    if (!up_) return;
    for (const ShapeProduction& p : grammar.productions) {
      if (!p.source_frame)
        throw InputError("the grammar file has no source frames (written by an older analyze); run analyze again to "
                         "generate upright variants");
      up_in_frame_.push_back(p.source_frame->rotation.transpose() * *up_);
    }
  }

  /// Candidates of a slot of `nonterminal` whose frame goes to the model by `world`.
  std::vector<std::size_t> at(std::size_t nonterminal, const RigidTransform& world) const {
    std::vector<std::size_t> list = by_lhs_[nonterminal];
    if (up_) {
      const Vec3 up_here = world.rotation.transpose() * *up_;
      std::erase_if(list, [&](std::size_t p) { return (up_in_frame_[p] - up_here).norm() > kUprightTolerance; });
    }
    return list;
  }

 private:
  std::vector<std::vector<std::size_t>> by_lhs_;
  std::optional<Vec3> up_;
  std::vector<Vec3> up_in_frame_;  // per production: the up axis in its lhs frame
};

// What a derivation places, meshes or points: the production's terminal, the collision test
// (Embree for triangles, shared cubes for points), how a placed piece joins the result.
struct MeshPlacement {
  using Piece = TriangleMesh;
  using Collisions = PieceCollisions;
  static const Piece& terminal(const ShapeProduction& p) { return p.terminal; }
  static std::size_t size(const Piece& piece) { return piece.triangles.size(); }
  static double default_seam_tolerance(double eps) { return eps; }
};

struct PointPlacement {
  using Piece = PointCloud;
  using Collisions = PointCollisions;
  static const Piece& terminal(const ShapeProduction& p) { return p.terminal_points; }
  static std::size_t size(const Piece& piece) { return piece.positions.size(); }
  // Points of two pieces share a cube of edge eps across their seam: within its diagonal.
  static double default_seam_tolerance(double eps) { return 2.0 * eps; }
};

// Per production (the axiom last): the amount (area, or points for a point-cloud grammar) its
// exemplar expansion places: its terminal's plus, for each slot, that of the production
// rebuilding the exemplar there.
std::vector<double> exemplar_expansions(const ContextFreeGrammar& grammar) {
  const bool points = grammar.of_points();
  const std::size_t n = grammar.productions.size();
  std::vector<double> amount(n + 1, -1.0);
  std::function<double(std::size_t)> of = [&](std::size_t i) {
    if (amount[i] >= 0.0) return amount[i];
    amount[i] = 0.0;  // a cycle (read_grammar rejects them) adds nothing instead of recursing forever
    const ShapeProduction& p = i < n ? grammar.productions[i] : grammar.axiom;
    double total = points ? static_cast<double>(p.terminal_points.positions.size()) : p.terminal.area();
    for (const ChildSlot& c : p.children) total += of(c.original_production);
    return amount[i] = total;
  };
  for (std::size_t i = 0; i <= n; ++i) of(i);
  return amount;
}

// One derivation drawing from `random`; nothing when a slot's exemplar production, placed after
// its random choices collided (or past the depth or size limits), would itself collide with
// what an earlier random choice put there. With options.exemplar_only nothing is checked.
// `expansions` as exemplar_expansions gives them: a slot takes a drawn production only when the
// amount the model would have if every open slot then took its exemplar production (`expected`)
// stays within options' size range, so the finished model's amount (`expected` at the end) does.
template <class Placement>
std::optional<ShapeDerivation> derive_once(const ContextFreeGrammar& grammar, const Candidates& choices, double eps,
                                           const ShapeDerivationOptions& options, const std::vector<double>& expansions,
                                           Random& random) {
  using Piece = typename Placement::Piece;
  constexpr bool points = std::is_same_v<Piece, PointCloud>;
  ShapeDerivation result;
  const double seam_tolerance = options.seam_tolerance > 0 ? options.seam_tolerance : Placement::default_seam_tolerance(eps);
  typename Placement::Collisions collisions(points ? eps : seam_tolerance);
  std::size_t placed_size = 0;
  const double exemplar_amount = expansions.back();
  const double lowest = options.min_size * exemplar_amount, highest = options.max_size * exemplar_amount;
  double expected = exemplar_amount;
  std::deque<OpenSlot> open;
  std::uint32_t placed = 0;  // pieces placed so far
  std::vector<std::uint32_t> seam_copies;  // per vertex of the result: its placed piece when on an open edge of it
  std::vector<std::vector<char>> open_of(grammar.productions.size() + 1);  // cache, filled on first use; the axiom last
  std::vector<char> open_known(grammar.productions.size() + 1, 0);
  // Adds production `index` (the axiom for productions.size()) already moved to `world` as
  // `piece` to the result; the caller has added `piece` to `collisions`.
  auto place = [&](std::size_t index, const RigidTransform& world, int depth, const Piece& piece) {
    const ShapeProduction& p = index < grammar.productions.size() ? grammar.productions[index] : grammar.axiom;
    if constexpr (points) {
      append_points(result.points, piece);
      result.point_nonterminal.resize(result.points.positions.size(), p.lhs);
    } else {
      if (!open_known[index]) open_of[index] = open_edge_vertices(p.terminal), open_known[index] = 1;
      append_seam_labels(seam_copies, open_of[index], placed++);
      append_mesh(result.mesh, piece);
      if (!options.weld_seams) result.triangle_nonterminal.resize(result.mesh.triangles.size(), p.lhs);
    }
    placed_size += Placement::size(piece);
    for (const ChildSlot& c : p.children) open.push_back({c, world.after(c.placement), depth + 1});
  };
  collisions.add(Placement::terminal(grammar.axiom));
  place(grammar.productions.size(), RigidTransform{}, 0, Placement::terminal(grammar.axiom));

  while (!open.empty()) {
    const OpenSlot slot = open.front();
    open.pop_front();
    const bool too_deep = slot.depth > options.max_depth;
    const bool too_big = placed_size > options.max_triangles;
    result.depth_limited = result.depth_limited || too_deep;
    result.triangle_limited = result.triangle_limited || too_big;
    const std::size_t original = slot.slot.original_production;
    std::vector<std::size_t> candidates = choices.at(slot.slot.nonterminal, slot.world);
    std::erase_if(candidates, [&](std::size_t p) {
      const double after = expected - expansions[original] + expansions[p];
      return p != original && (after < lowest || after > highest);
    });
    std::optional<std::pair<std::size_t, Piece>> accepted;  // production and its moved terminal
    if (!options.exemplar_only && !too_deep && !too_big && !candidates.empty()) {
      for (int attempt = 0; attempt < options.retries && !accepted; ++attempt) {
        const std::size_t pick = candidates[static_cast<std::size_t>(random.uniform() * static_cast<double>(candidates.size()))];
        const ShapeProduction& p = grammar.productions[pick];
        Piece piece = transformed(Placement::terminal(p), slot.world);
        if (!collisions.add_unless_collides(piece, contact_of(grammar, p, slot.world, seam_tolerance))) {
          ++result.collisions_retried;
          continue;
        }
        accepted.emplace(pick, std::move(piece));
      }
      if (!accepted) ++result.fallbacks;
    }
    if (!accepted) {
      const ShapeProduction& p = grammar.productions[original];
      Piece piece = transformed(Placement::terminal(p), slot.world);
      if (options.exemplar_only)
        collisions.add(piece);
      else if (!collisions.add_unless_collides(piece, contact_of(grammar, p, slot.world, seam_tolerance)))
        return std::nullopt;
      accepted.emplace(original, std::move(piece));
    }
    result.productions.push_back(accepted->first);
    result.changed = result.changed || accepted->first != original;
    expected += expansions[accepted->first] - expansions[original];
    place(accepted->first, slot.world, slot.depth, accepted->second);
  }
  if (!points && options.weld_seams) {
    resolve_t_junctions(result.mesh, seam_weld_tolerance(grammar, eps), &seam_copies, kSeamWeldFloorFraction * eps);
    close_triangular_holes(result.mesh, kSeamHoleFraction * eps);
    drop_hanging_slivers(result.mesh, seam_weld_tolerance(grammar, eps));
    result.mesh = merge_flat_faces(result.mesh);
  }
  return result;
}

// derive_shape for meshes or points.
template <class Placement>
ShapeDerivation derive(const ContextFreeGrammar& grammar, double eps, const ShapeDerivationOptions& options) {
  const Candidates choices(grammar, options.up);
  const std::vector<double> expansions = exemplar_expansions(grammar);
  Random random(options.seed);
  std::size_t restarts = 0;
  for (; restarts <= options.restarts; ++restarts)
    if (std::optional<ShapeDerivation> derived = derive_once<Placement>(grammar, choices, eps, options, expansions, random)) {
      derived->restarts = restarts;
      return std::move(*derived);
    }
  ShapeDerivationOptions rebuild = options;
  rebuild.exemplar_only = true;
  ShapeDerivation exemplar = *derive_once<Placement>(grammar, choices, eps, rebuild, expansions, random);
  exemplar.restarts = restarts;
  return exemplar;
}

}  // namespace

bool derivation_has_choice(const ContextFreeGrammar& grammar, const ShapeDerivationOptions& options) {
  if (grammar.empty() || options.exemplar_only) return false;
  const Candidates choices(grammar, options.up);
  const std::vector<double> expansions = exemplar_expansions(grammar);
  const double exemplar_amount = expansions.back();
  std::vector<OpenSlot> open;
  for (const ChildSlot& c : grammar.axiom.children) open.push_back({c, c.placement, 1});
  while (!open.empty()) {
    const OpenSlot slot = open.back();
    open.pop_back();
    if (slot.depth > options.max_depth) continue;
    const std::size_t original = slot.slot.original_production;
    for (std::size_t p : choices.at(slot.slot.nonterminal, slot.world)) {
      const double size = exemplar_amount > 0.0 ? (exemplar_amount - expansions[original] + expansions[p]) / exemplar_amount : 1.0;
      if (p != original && size >= options.min_size && size <= options.max_size) return true;
    }
    for (const ChildSlot& c : grammar.productions[slot.slot.original_production].children)
      open.push_back({c, slot.world.after(c.placement), slot.depth + 1});
  }
  return false;
}

ShapeDerivation derive_shape(const ContextFreeGrammar& grammar, double eps, const ShapeDerivationOptions& options) {
  if (grammar.empty()) throw std::invalid_argument("derive_shape: the grammar has no context-free rules");
  return grammar.of_points() ? derive<PointPlacement>(grammar, eps, options) : derive<MeshPlacement>(grammar, eps, options);
}

}  // namespace dg
