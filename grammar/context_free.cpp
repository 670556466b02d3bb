#include "grammar/context_free.h"

#include "geometry/cleaning.h"
#include "geometry/flat_faces.h"
#include "geometry/fragment_merge.h"
#include "geometry/submesh.h"
#include "geometry/topology.h"
#include "geometry/zone_cut.h"
#include "grammar/cell_sets.h"
#include "grammar/rule_pruning.h"
#include "grammar/seam_curve.h"
#include "grammar/seam_cut.h"
#include "grammar/seam_plane.h"
#include "geometry/random.h"
#include "geometry/same_surface.h"
#include "grammar/same_production.h"
#include "grammar/site_conflicts.h"
#include "grammar/site_loops.h"
#include "symmetry/symmetric_region.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iterator>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <unordered_map>

namespace dg {
namespace {

using Cells = std::vector<std::uint32_t>;
constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
// Seam cuts move vertices within this fraction of eps onto their planes (no slivers thinner).
constexpr double kCutSnapFraction = 1e-5;
// A plane seam that grazes other geometry is moved by up to kPlaneShiftSteps steps of
// kPlaneShiftStepFraction eps either way; its first location's seam curve must then lie within
// kCurveOnPlaneFraction eps of it.
constexpr int kPlaneShiftSteps = 4;
constexpr double kPlaneShiftStepFraction = 0.25;
constexpr double kCurveOnPlaneFraction = 1e-3;
// Locations of a class tried as the one the others' seams must fit (the first, and when it
// leaves some out, up to this many in all; the chandelier has classes of 37).
constexpr std::size_t kMaxReferenceTrials = 16;
// A plane seam through a band that is not flat must leave at least this gap (fraction of eps)
// between the voxels next to the band on the docker's side and those on the rest's side.
constexpr double kMinSeamGapFraction = 0.25;

// Cells listed in both ascending lists.
std::size_t shared_cells(const Cells& a, const Cells& b) {
  std::size_t shared = 0;
  for (std::size_t i = 0, j = 0; i < a.size() && j < b.size();) {
    if (a[i] == b[j]) {
      ++shared, ++i, ++j;
    } else if (a[i] < b[j]) {
      ++i;
    } else {
      ++j;
    }
  }
  return shared;
}

// Share of the shorter list's cells that the other list holds too (1 when either is empty).
double share_of_smaller(const Cells& a, const Cells& b) {
  const std::size_t smaller = std::min(a.size(), b.size());
  return smaller == 0 ? 1.0 : static_cast<double>(shared_cells(a, b)) / static_cast<double>(smaller);
}

bool share_a_cell(const Cells& a, const Cells& b) {
  for (std::size_t i = 0, j = 0; i < a.size() && j < b.size();) {
    if (a[i] == b[j]) return true;
    if (a[i] < b[j])
      ++i;
    else
      ++j;
  }
  return false;
}

struct Node {
  Cells site, docker;
  std::size_t klass = kNone;
  RigidTransform frame;  // non-terminal frame -> this location
  RigidTransform frame_inverse;
  std::vector<std::uint32_t> piece;  // triangles of the cut exemplar (or points of a cloud) in the docker, ascending
  bool kept = true;
  std::size_t parent = kNone;
  std::vector<std::size_t> children;
  std::size_t first_production = kNoProduction;
  double aligned_by = 0.0;  // how far align_frames moved its seam curve (model units), 0 when not
};

struct Relation {
  std::size_t from, to;
  RigidTransform motion;  // frame(to) = motion after frame(from)
};

// Whether cleaning would drop a triangle of `mesh` as degenerate: a piece holding one opens a
// hole wherever it is placed.
bool has_degenerate_triangle(const TriangleMesh& mesh) {
  return std::any_of(mesh.triangles.begin(), mesh.triangles.end(), [&](const Triangle& t) { return is_degenerate(mesh, t); });
}

class Builder {
 public:
  Builder(const PreparedModel& prepared, const ContextFreeOptions& options, const ProgressCallback& progress)
      : surface_(prepared.surface),
        mesh_(prepared.model.mesh),
        cloud_(prepared.model.is_point_cloud() ? &prepared.model.cloud : nullptr),
        options_(options),
        progress_(progress),
        exemplar_closed_(is_closed_and_oriented(mesh_)) {}

  ContextFreeGrammar build(const DockingSiteResult& sites, ContextFreeStats& stats) {
    collect_nodes(sites, stats);
    assign_classes(stats);
    choose_seams();
    if (cloud_) {
      point_pieces();
    } else {
      screen_fit();
      cut_model();
      cut_pieces();
      check_fit();
    }
    report(0.95);
    if (!cloud_) join_fragments();
    count_sites(stats);
    build_tree();
    ContextFreeGrammar grammar;
    make_productions(grammar, stats);
    report(1.0);
    stats.nodes = 0;
    for (const Node& n : nodes_) stats.nodes += n.kept ? 1 : 0;
    return grammar;
  }

 private:
  // The location of a docker and its site: an earlier one when the dockers are the same cells
  // (Jaccard 0.8) but for fewer than half the smaller site's count, and the smaller site lies
  // in the other (0.8 of its cells: one motion's band can be a part of another's around the
  // same docker), else a new one (kNone past max_nodes). Seen on the bundled models, dockers of
  // one location differ by at most a fifth of a site, near the seam. A big docker ending a
  // board's thickness higher, or holding one more piece (a stair's step with the column's
  // foot), still shares 80% of its cells with the other, and its band most of the other's at
  // some phases of the voxel grid; those are other locations.
  std::size_t add_node(const Cells& site, const Cells& docker) {
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      const Node& n = nodes_[i];
      const double size_ratio = static_cast<double>(std::min(n.docker.size(), docker.size())) /
                                static_cast<double>(std::max<std::size_t>(1, std::max(n.docker.size(), docker.size())));
      if (size_ratio < 0.8) continue;
      const std::size_t shared = shared_cells(n.docker, docker);
      const std::size_t together = n.docker.size() + docker.size() - shared;
      const double jaccard = together == 0 ? 1.0 : static_cast<double>(shared) / static_cast<double>(together);
      if (jaccard >= 0.8 && 2 * (together - shared) <= std::min(n.site.size(), site.size()) &&
          share_of_smaller(n.site, site) >= 0.8)
        return i;
    }
    if (nodes_.size() >= options_.max_nodes) return kNone;
    Node node;
    node.site = site;
    node.docker = docker;
    nodes_.push_back(std::move(node));
    return nodes_.size() - 1;
  }

  void collect_nodes(const DockingSiteResult& sites, ContextFreeStats& stats) {
    for (const DockingSite& s : sites.sites) {
      if (s.slippable) {
        ++stats.sites_slippable;
        continue;
      }
      if (s.stray_seam) {
        ++stats.sites_stray_seam;
        continue;
      }
      const std::size_t a = add_node(s.site, s.docker);
      const std::size_t b = add_node(s.secondary_site, s.secondary_docker);
      if (a == kNone || b == kNone || a == b) continue;
      relations_.push_back({a, b, s.transform});
    }
  }

  // Non-terminals: nodes connected by site motions, frames composed along a spanning tree. A
  // relation connects two locations unless the docker of one, put in place of the other's, leaves
  // that site's loops in more groups than its own docker does (site_loops): a piece that only
  // caps each of eight stems, put where a whole subtree joined them, would leave the model in
  // floating parts, each closed and r-similar.
  void assign_classes(ContextFreeStats& stats) {
    std::vector<SiteLoops> loops(nodes_.size());
    std::vector<std::size_t> own_groups(nodes_.size());  // the exemplar's groups at each location
    tbb::parallel_for(std::size_t(0), nodes_.size(), [&](std::size_t i) {
      loops[i] = site_loops(surface_, nodes_[i].site, nodes_[i].docker);
      own_groups[i] = *joined_loop_groups(surface_, nodes_[i].site, loops[i], loops[i], RigidTransform{});
    });
    // Whether the docker of `from` (carried onto `to` by `motion`) in place of that of `to` keeps
    // its loops joined (also when its loops land on no loop of `to`: nothing to compare).
    auto keeps_joined = [&](std::size_t from, std::size_t to, const RigidTransform& motion) {
      const std::optional<std::size_t> swapped = joined_loop_groups(surface_, nodes_[to].site, loops[to], loops[from], motion);
      return !swapped || *swapped <= own_groups[to];
    };
    std::vector<std::vector<std::pair<std::size_t, RigidTransform>>> edges(nodes_.size());
    std::set<std::pair<std::size_t, std::size_t>> kept_apart;
    for (const Relation& r : relations_) {
      if (!keeps_joined(r.from, r.to, r.motion) || !keeps_joined(r.to, r.from, r.motion.inverse())) {
        kept_apart.insert(std::minmax(r.from, r.to));
        continue;
      }
      edges[r.from].push_back({r.to, r.motion});
      edges[r.to].push_back({r.from, r.motion.inverse()});
    }
    for (std::size_t start = 0; start < nodes_.size(); ++start) {
      if (nodes_[start].klass != kNone || edges[start].empty()) continue;
      const std::size_t klass = class_nodes_.size();
      class_nodes_.emplace_back();
      nodes_[start].klass = klass;
      nodes_[start].frame = RigidTransform{};
      std::vector<std::size_t> queue{start};
      for (std::size_t head = 0; head < queue.size(); ++head) {
        const std::size_t u = queue[head];
        class_nodes_[klass].push_back(u);
        for (const auto& [v, motion] : edges[u]) {
          if (nodes_[v].klass != kNone) continue;
          nodes_[v].klass = klass;
          nodes_[v].frame = motion.after(nodes_[u].frame);
          queue.push_back(v);
        }
      }
    }
    for (Node& n : nodes_) {
      n.kept = n.klass != kNone;
      n.frame_inverse = n.frame.inverse();
    }
    // Pairs some other relation joined after all do not count.
    stats.locations_kept_apart = static_cast<std::size_t>(std::count_if(kept_apart.begin(), kept_apart.end(), [&](const auto& pair) {
      return nodes_[pair.first].klass != nodes_[pair.second].klass || nodes_[pair.first].klass == kNone;
    }));
  }

  // One seam per non-terminal, from its first location: a plane when the band lies flat and the
  // docker is on one side of it at every location, else a plane that parts the docker from the
  // rest at every location however the band is shaped (plane_between_sides), else the voxel
  // faces inside the band. A plane adds triangles only along its seam curve; voxel faces cut
  // the band's triangles into staircases.
  // The first location of class k: the one its seam and reference cells come from.
  const Node& first_location(std::size_t k) const { return nodes_[class_nodes_[k].front()]; }

  void choose_seams() {
    const double flatness = 2.0 * surface_.eps();
    class_seam_.assign(class_nodes_.size(), SeamSurface{});
    class_docker_side_.assign(class_nodes_.size(), {});
    class_face_index_.clear();
    for (std::size_t k = 0; k < class_nodes_.size(); ++k) {
      const Node& root = first_location(k);
      std::optional<Plane> plane = flat_band_plane(k, flatness);
      if (!plane) {
        std::vector<SeamLocation> locations;
        for (std::size_t i : class_nodes_[k]) locations.push_back({&nodes_[i].site, &nodes_[i].docker, nodes_[i].frame_inverse});
        plane = plane_between_sides(surface_, locations, kMinSeamGapFraction * surface_.eps());
      }
      SeamSurface& seam = class_seam_[k];
      if (plane) {
        seam.kind = SeamSurface::Kind::plane;
        seam.normal = plane->normal;
        seam.offset = plane->offset;
      } else {
        seam = voxel_seam(surface_, root.site, root.docker, class_docker_side_[k]);
        if (seam.faces.empty())
          for (std::size_t i : class_nodes_[k]) nodes_[i].kept = false;
      }
      class_face_index_.emplace_back(seam);
    }
  }

  // A plane through a band can also graze geometry beyond the docker that the band only partly
  // holds (a rail leaving a post just above the post's band, where the voxel grid's phase puts
  // the band a layer higher): the first location's seam curve then follows that geometry's edges
  // off the plane, and the other locations' curves cannot fit it. Moves such a plane of class k
  // along its normal, a quarter voxel at a time up to one voxel either way (nearest first), to
  // the first offset where that curve lies on the plane and every location's docker stays on its
  // positive side. False, with the plane unmoved, when the curve lies on the plane already or no
  // such offset exists.
  bool move_plane_off_other_geometry(std::size_t k) {
    SeamSurface& seam = class_seam_[k];
    const Node& root = first_location(k);
    if (seam.kind != SeamSurface::Kind::plane || curve_on_plane(own_seam_curve(root), seam)) return false;
    const double start = seam.offset, step = kPlaneShiftStepFraction * surface_.eps();
    for (int i = 1; i <= 2 * kPlaneShiftSteps; ++i) {
      const int steps = (i + 1) / 2 * (i % 2 == 1 ? 1 : -1);  // 1, -1, 2, -2, ...
      seam.offset = start + steps * step;
      if (docker_sides_hold(k, Plane{seam.normal, seam.offset}) && curve_on_plane(own_seam_curve(root), seam)) return true;
    }
    seam.offset = start;
    return false;
  }

  // Whether every location of class k keeps its docker on the positive side of `plane` (in the
  // non-terminal's frame), placed by the location's frame.
  bool docker_sides_hold(std::size_t k, const Plane& plane) const {
    for (std::size_t i : class_nodes_[k]) {
      const Node& n = nodes_[i];
      Plane placed = plane.moved(n.frame);
      const Vec3 normal = placed.normal;
      if (!orient_towards_docker(surface_, n.docker, mask_of(n.site, surface_.cell_count()), placed) ||
          placed.normal.dot(normal) < 0)
        return false;
    }
    return true;
  }

  // Whether a seam curve (in the seam's frame) is not empty and lies on the plane `seam`.
  bool curve_on_plane(const std::vector<Segment>& curve, const SeamSurface& seam) const {
    const double tolerance = kCurveOnPlaneFraction * surface_.eps();
    for (const Segment& segment : curve)
      for (const Vec3& p : segment)
        if (std::abs(seam.normal.dot(p) - seam.offset) > tolerance) return false;
    return !curve.empty();
  }

  // The least-squares plane of class k's first band (in the non-terminal frame), when every
  // location's band lies within 1.5 `flatness` of it (placed by its frame) and its docker on
  // the positive side.
  std::optional<Plane> flat_band_plane(std::size_t k, double flatness) const {
    const Node& root = first_location(k);
    std::optional<Plane> plane = fit_band_plane(surface_, root.site, flatness);
    if (!plane || !orient_towards_docker(surface_, root.docker, mask_of(root.site, surface_.cell_count()), *plane)) return std::nullopt;
    for (std::size_t i : class_nodes_[k]) {
      const Plane placed = plane->moved(nodes_[i].frame);
      for (std::uint32_t c : nodes_[i].site)
        if (std::abs(placed.distance(surface_.centre(c))) > 1.5 * flatness) return std::nullopt;
    }
    if (!docker_sides_hold(k, *plane)) return std::nullopt;
    return plane;
  }

  // Original triangles touching the listed cells, one flag per triangle of the exemplar.
  std::vector<char> triangles_touching(const Cells& cells) const {
    std::vector<char> touching(mesh_.triangles.size(), 0);
    for (std::uint32_t c : cells)
      for (std::uint32_t t : surface_.triangles(c)) touching[t] = 1;
    return touching;
  }

  // Shares of the run, measured on the corpus: cutting along the seams about two thirds, finding
  // the dockers' pieces a quarter, the rest a tenth.
  static constexpr double kCutShare = 0.65, kPiecesShare = 0.25;

  void report(double fraction) const { report_progress(progress_, "context-free rules", fraction); }

  // Runs body(i) for every kept node i in parallel (nodes must be independent), reporting the
  // stage's progress from `from` to `to` as they are done.
  void for_kept_nodes(double from, double to, const std::function<void(std::size_t)>& body) const {
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < nodes_.size(); ++i)
      if (nodes_[i].kept) kept.push_back(i);
    const ProgressCallback within = [&](std::string_view stage, double fraction) {
      return !progress_ || progress_(stage, from + (to - from) * fraction);
    };
    parallel_for_reporting(kept.size(), within, "context-free rules", [&](std::size_t k) { body(kept[k]); });
  }

  // How far seam cuts move vertices onto their planes (model units).
  double snap_distance() const { return kCutSnapFraction * surface_.eps(); }

  // `segments` (model frame) moved into the non-terminal frame of `node`.
  static std::vector<Segment> in_frame(std::vector<Segment> segments, const Node& node) {
    for (Segment& s : segments) s = {node.frame_inverse.apply(s[0]), node.frame_inverse.apply(s[1])};
    return segments;
  }

  // Keeps, in each class, the locations whose seam curve (`curve_of`, in the non-terminal's
  // frame) lies within `limit` (model units) of its reference location's: the first location,
  // or when that leaves some out, the one of the first kMaxReferenceTrials kept locations that
  // the most others fit (the metal gate's class of 12 whose first fits none, 7 of the others
  // fit one another). A class left with fewer than two locations (a non-terminal needs an
  // alternative) loses them all. Returns each class's largest misfit kept.
  // `only`: one flag per class, the classes to judge (empty: all).
  template <class CurveOf>
  std::vector<double> keep_fitting_locations(const CurveOf& curve_of, double limit, const std::vector<char>& only = {}) {
    // An empty curve never fits: seam_misfit is infinite when the reference has no match.
    return keep_locations(curve_of, [&](const std::vector<Segment>& curve, const std::vector<Segment>& reference) {
      return seam_misfit(curve, reference, limit, surface_.eps());
    }, limit, only);
  }

  // keep_fitting_locations for any seam shape: `shape_of(node)` gives what a location's seam
  // looks like in the non-terminal's frame (nothing fits an empty one), `misfit(shape,
  // reference shape)` how far it lies from the reference location's (model units).
  template <class ShapeOf, class Misfit>
  std::vector<double> keep_locations(const ShapeOf& shape_of, const Misfit& misfit_of, double limit,
                                     const std::vector<char>& only = {}) {
    std::vector<double> largest(class_nodes_.size(), 0.0);
    for (std::size_t k = 0; k < class_nodes_.size(); ++k) {
      if (!only.empty() && !only[k]) continue;
      const std::vector<std::size_t>& members = class_nodes_[k];
      using Shape = decltype(shape_of(nodes_[members.front()]));
      std::vector<Shape> shapes(members.size());
      for (std::size_t i = 0; i < members.size(); ++i)
        if (nodes_[members[i]].kept) shapes[i] = shape_of(nodes_[members[i]]);
      // Each location's misfit against location `reference` (infinite for one not kept).
      auto misfits_to = [&](std::size_t reference) {
        std::vector<double> misfit(members.size(), std::numeric_limits<double>::infinity());
        if (shapes[reference].empty()) return misfit;
        for (std::size_t i = 0; i < members.size(); ++i)
          if (!shapes[i].empty()) misfit[i] = i == reference ? 0.0 : misfit_of(shapes[i], shapes[reference]);
        return misfit;
      };
      auto fitting = [&](const std::vector<double>& misfit) {
        return std::count_if(misfit.begin(), misfit.end(), [&](double m) { return m <= limit; });
      };
      const auto candidates = std::count_if(shapes.begin(), shapes.end(), [](const Shape& s) { return !s.empty(); });
      std::vector<double> best = misfits_to(0);
      for (std::size_t r = 1; r < std::min(members.size(), kMaxReferenceTrials) && fitting(best) < candidates; ++r) {
        if (shapes[r].empty()) continue;
        std::vector<double> misfit = misfits_to(r);
        if (fitting(misfit) > fitting(best)) best = std::move(misfit);
      }
      std::size_t kept = 0;
      for (std::size_t i = 0; i < members.size(); ++i) {
        Node& n = nodes_[members[i]];
        n.kept = best[i] <= limit;
        if (n.kept) largest[k] = std::max(largest[k], best[i]), ++kept;
      }
      if (kept < 2)
        for (std::size_t i : members) nodes_[i].kept = false;
    }
    return largest;
  }

  std::size_t kept_nodes() const {
    return static_cast<std::size_t>(std::count_if(nodes_.begin(), nodes_.end(), [](const Node& n) { return n.kept; }));
  }

  // The exemplar cut along the seams of all kept locations (each in its own frame), once: every
  // piece of every production is a set of its triangles.
  void cut_model() {
    cut_ = mesh_;
    origin_.resize(mesh_.triangles.size());
    std::iota(origin_.begin(), origin_.end(), 0u);
    const double tolerance = snap_distance();
    const double total = static_cast<double>(std::max<std::size_t>(1, kept_nodes()));
    std::size_t done = 0;
    for (const Node& n : nodes_) {
      if (!n.kept) continue;
      report(kCutShare * static_cast<double>(done++) / total);
      const std::vector<char> touching = triangles_touching(n.site);
      std::vector<char> zone(cut_.triangles.size(), 0);
      for (std::size_t t = 0; t < cut_.triangles.size(); ++t) zone[t] = touching[origin_[t]] && near_band(cut_, n, t);
      ZoneCut cut = cut_zone(cut_, zone, seam_planes(class_seam_[n.klass], n.frame), tolerance, seam_face_filter(n));
      for (std::uint32_t& o : cut.origin) o = origin_[o];
      cut_ = std::move(cut.mesh);
      origin_ = std::move(cut.origin);
    }
  }

  // For voxel seams: cut a piece along a voxel plane only where a seam face on that plane meets
  // its box (in the seam's frame).
  PieceFilter seam_face_filter(const Node& node) const {
    const SeamSurface& seam = class_seam_[node.klass];
    if (seam.kind != SeamSurface::Kind::voxel_faces) return {};
    return [&faces = class_face_index_[node.klass], frame = node.frame, back = node.frame_inverse](
               const std::array<Vec3, 3>& corners, std::size_t axis, double offset) {
      const std::array<Vec3, 3> own{back.apply(corners[0]), back.apply(corners[1]), back.apply(corners[2])};
      const double base = frame.rotation.col(static_cast<Eigen::Index>(axis)).dot(frame.translation);
      const auto plane = static_cast<std::int32_t>(std::lround((offset - base) / faces.eps()));
      return crosses_face(faces, own, static_cast<int>(axis), plane);
    };
  }

  // The seam curve of `node` cut alone: the exemplar triangles around its site and docker cut
  // along its own seam only, in the non-terminal's frame. The same curve as in the cumulative
  // cut (other locations' cuts only add vertices along it), at a fraction of the cost.
  std::vector<Segment> own_seam_curve(const Node& node) const {
    Cells cells = node.docker;
    cells.insert(cells.end(), node.site.begin(), node.site.end());
    const std::vector<char> around = triangles_touching(cells), in_band = triangles_touching(node.site);
    std::vector<std::size_t> triangles;
    for (std::size_t t = 0; t < around.size(); ++t)
      if (around[t]) triangles.push_back(t);
    const TriangleMesh local = submesh(mesh_, triangles);
    std::vector<char> zone(local.triangles.size(), 0);
    for (std::size_t t = 0; t < local.triangles.size(); ++t) zone[t] = in_band[triangles[t]] && near_band(local, node, t);
    const ZoneCut cut = cut_zone(local, zone, seam_planes(class_seam_[node.klass], node.frame),
                                 snap_distance(), seam_face_filter(node));
    std::vector<std::uint32_t> piece;
    std::vector<char> inside(cut.mesh.triangles.size(), 0);
    for (std::uint32_t t = 0; t < cut.mesh.triangles.size(); ++t)
      if (in_docker(cut.mesh, node, t)) piece.push_back(t), inside[t] = 1;
    return in_frame(seam_segments(cut.mesh, edge_users(cut.mesh), piece, inside), node);
  }

  // Before the cumulative cut, after align_frames: locations whose own seam curve lies more
  // than twice the fit limit from their class's reference location's are dropped, and so are
  // classes left with fewer than two locations, so the whole model is not cut for locations
  // check_fit would drop (it decides on the cumulative cut, within the limit itself).
  // A plane class that loses locations this way while its plane grazes other geometry gets one
  // more try with the plane moved off it (move_plane_off_other_geometry), its locations as they
  // were before; the try stays when it keeps more locations.
  void screen_fit() {
    // What the screen (align_frames, keep_locations) changes in a node.
    struct Placement {
      bool kept;
      RigidTransform frame, frame_inverse;
      double aligned_by;
    };
    auto placement = [&](std::size_t i) {
      const Node& n = nodes_[i];
      return Placement{n.kept, n.frame, n.frame_inverse, n.aligned_by};
    };
    auto place = [&](std::size_t i, const Placement& p) {
      Node& n = nodes_[i];
      n.kept = p.kept;
      n.frame = p.frame;
      n.frame_inverse = p.frame_inverse;
      n.aligned_by = p.aligned_by;
    };
    std::vector<std::vector<Segment>> curves(nodes_.size());
    // Progress stays at 0 during the screen (the cut reports from 0 on); a cancel is still heard.
    for_kept_nodes(0.0, 0.0, [&](std::size_t i) { curves[i] = own_seam_curve(nodes_[i]); });
    std::vector<Placement> before;
    for (std::size_t i = 0; i < nodes_.size(); ++i) before.push_back(placement(i));
    auto screen = [&](const std::vector<char>& only) {
      align_frames(curves, only);
      keep_fitting_locations([&](const Node& n) { return curves[static_cast<std::size_t>(&n - nodes_.data())]; },
                             2.0 * kSeamFitFraction * surface_.eps(), only);
    };
    screen({});
    for (std::size_t k = 0; k < class_nodes_.size(); ++k) {
      const std::vector<std::size_t>& members = class_nodes_[k];
      auto kept = [&] { return std::count_if(members.begin(), members.end(), [&](std::size_t i) { return nodes_[i].kept; }); };
      const auto kept_first = kept();
      const auto kept_before = std::count_if(members.begin(), members.end(), [&](std::size_t i) { return before[i].kept; });
      if (kept_first == kept_before) continue;
      const double offset = class_seam_[k].offset;
      if (!move_plane_off_other_geometry(k)) continue;
      std::vector<Placement> first;
      std::vector<std::vector<Segment>> first_curves;
      for (std::size_t i : members) first.push_back(placement(i)), first_curves.push_back(curves[i]);
      for (std::size_t i : members) {
        place(i, before[i]);
        curves[i] = nodes_[i].kept ? own_seam_curve(nodes_[i]) : std::vector<Segment>{};
      }
      std::vector<char> only(class_nodes_.size(), 0);
      only[k] = 1;
      screen(only);
      if (kept() > kept_first) continue;
      class_seam_[k].offset = offset;
      for (std::size_t m = 0; m < members.size(); ++m) {
        place(members[m], first[m]);
        curves[members[m]] = std::move(first_curves[m]);
      }
    }
  }

  // Hand-placed repeats sit a little off the motion that relates them (the table football's
  // rods: up to 0.13 eps), more than a seam may misfit. A location whose seam curve misses its
  // class's first one, at a length within kSeamAlignLengthFraction of it (a rigid motion keeps
  // lengths: curves of other lengths are other seams), gets its frame moved by the motion that
  // carries its curve onto the first (align_seam_curve, within kSeamAlignReachFraction eps and
  // kSeamAlignMaxAngle), and its curve is cut again along the moved seam; the fit screen then
  // decides. `curves[i]`: node i's own seam curve in its non-terminal's frame, updated.
  // `only`: one flag per class, the classes to align (empty: all).
  void align_frames(std::vector<std::vector<Segment>>& curves, const std::vector<char>& only = {}) {
    const double eps = surface_.eps(), reach = kSeamAlignReachFraction * eps, limit = kSeamFitFraction * eps;
    for (std::size_t k = 0; k < class_nodes_.size(); ++k) {
      if (!only.empty() && !only[k]) continue;
      const std::vector<std::size_t>& members = class_nodes_[k];
      const std::vector<Segment>& reference = curves[members.front()];
      if (!nodes_[members.front()].kept || reference.empty()) continue;
      const double reference_length = curve_length(reference);
      for (std::size_t i : members) {
        Node& n = nodes_[i];
        if (i == members.front() || !n.kept) continue;
        // A rigid motion keeps a curve's length: curves of clearly other lengths are other seams.
        if (std::abs(curve_length(curves[i]) - reference_length) > kSeamAlignLengthFraction * reference_length) continue;
        if (seam_misfit(curves[i], reference, limit, eps) <= limit) continue;
        const std::optional<RigidTransform> correction = align_seam_curve(curves[i], reference, reach, eps);
        if (!correction || correction->angle() > kSeamAlignMaxAngle) continue;
        for (const Segment& s : curves[i])
          for (const Vec3& p : s) n.aligned_by = std::max(n.aligned_by, (correction->apply(p) - p).norm());
        n.frame = n.frame.after(correction->inverse());
        n.frame_inverse = n.frame.inverse();
        curves[i] = own_seam_curve(n);
      }
    }
  }

  // Whether the box around triangle t of the cut model holds a band cell of `node`, or, moved to
  // the class's first location, one of that location's band cells (true for triangles spanning
  // many voxels). Where a motion does not carry the voxel grid onto itself, the bands of two
  // locations are voxelized differently; the first location's band, moved, is the same at all.
  bool near_band(const TriangleMesh& mesh, const Node& node, std::size_t t) const {
    const Node& root = first_location(node.klass);
    BoundingBox mapped;
    for (const Vec3& p : mesh.corners(t)) mapped.add(node.frame_inverse.apply(p));
    if (near_cells(mapped, root.site)) return true;
    BoundingBox box;
    for (const Vec3& p : mesh.corners(t)) box.add(p);
    return near_cells(box, node.site);
  }

  // Whether a cell of `site` (ascending) lies among the voxels the box `box` touches (true for
  // boxes of more than 64 voxels).
  bool near_cells(const BoundingBox& box, const Cells& site) const {
    const VoxelCoord lo = surface_.voxel_of(box.min), hi = surface_.voxel_of(box.max);
    if (static_cast<std::int64_t>(hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1) > 64) return true;
    for (std::int32_t i = lo[0]; i <= hi[0]; ++i)
      for (std::int32_t j = lo[1]; j <= hi[1]; ++j)
        for (std::int32_t k = lo[2]; k <= hi[2]; ++k) {
          const std::int64_t cell = surface_.find({i, j, k});
          if (cell >= 0 && std::binary_search(site.begin(), site.end(), static_cast<std::uint32_t>(cell))) return true;
        }
    return false;
  }

  // Whether triangle t of the cut model lies in the docker of `node`: where its centroid, moved to
  // the class's first location, falls in that location's band, on the docker side of the seam
  // (so every location's seam neighbourhood is judged alike, whatever its own voxels); elsewhere
  // in the location's own docker cells, or in its own band on the docker side. The dockers
  // themselves may differ in extent from location to location (only their seams match).
  bool in_docker(const TriangleMesh& mesh, const Node& node, std::size_t t) const {
    const auto corners = mesh.corners(t);
    const Vec3 centroid = (corners[0] + corners[1] + corners[2]) / 3.0;
    const Node& root = first_location(node.klass);
    const std::int64_t at_root = nearest_cell(surface_, node.frame_inverse.apply(centroid));
    if (at_root >= 0 && std::binary_search(root.site.begin(), root.site.end(), static_cast<std::uint32_t>(at_root)))
      return on_docker_side(class_seam_[node.klass], surface_, class_docker_side_[node.klass], node.frame_inverse, centroid);
    const std::int64_t found = nearest_cell(surface_, centroid);
    if (found < 0) return false;
    const auto cell = static_cast<std::uint32_t>(found);
    if (std::binary_search(node.docker.begin(), node.docker.end(), cell)) return true;
    if (!std::binary_search(node.site.begin(), node.site.end(), cell)) return false;
    return on_docker_side(class_seam_[node.klass], surface_, class_docker_side_[node.klass], node.frame_inverse, centroid);
  }

  // The docker piece of every kept node: triangles of the cut model, ascending.
  void cut_pieces() {
    std::vector<std::vector<std::uint32_t>> pieces_of_original(mesh_.triangles.size());
    for (std::uint32_t t = 0; t < cut_.triangles.size(); ++t) pieces_of_original[origin_[t]].push_back(t);
    for_kept_nodes(kCutShare, kCutShare + kPiecesShare, [&](std::size_t i) {
      Node& n = nodes_[i];
      Cells cells = n.docker;
      cells.insert(cells.end(), n.site.begin(), n.site.end());
      const std::vector<char> touching = triangles_touching(cells);
      for (std::size_t o = 0; o < touching.size(); ++o)
        if (touching[o])
          for (std::uint32_t t : pieces_of_original[o])
            if (in_docker(cut_, n, t)) n.piece.push_back(t);
      std::sort(n.piece.begin(), n.piece.end());
    });
  }

  // The docker piece of every kept node of a point cloud: the points in its docker cells and, in
  // its band cells, those on the docker side of its seam; ascending. Points have no seam curve:
  // a location is kept when its docker's points next to the seam look as the reference location's
  // (seam_layer; the misfit is recorded as 0).
  void point_pieces() {
    std::vector<std::vector<std::uint32_t>> cell_points(surface_.cell_count());
    for (std::uint32_t p = 0; p < cloud_->positions.size(); ++p) {
      const std::int64_t cell = nearest_cell(surface_, cloud_->positions[p]);
      if (cell >= 0) cell_points[static_cast<std::size_t>(cell)].push_back(p);
    }
    std::vector<std::vector<Vec3>> layers(nodes_.size());
    const double total = static_cast<double>(std::max<std::size_t>(1, kept_nodes()));
    std::size_t done = 0;
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      Node& n = nodes_[i];
      if (!n.kept) continue;
      report(0.9 * static_cast<double>(done++) / total);
      for (std::uint32_t c : n.docker) n.piece.insert(n.piece.end(), cell_points[c].begin(), cell_points[c].end());
      for (std::uint32_t c : n.site)
        for (std::uint32_t p : cell_points[c])
          if (on_docker_side(class_seam_[n.klass], surface_, class_docker_side_[n.klass], n.frame_inverse, cloud_->positions[p]))
            n.piece.push_back(p);
      std::sort(n.piece.begin(), n.piece.end());
      n.piece.erase(std::unique(n.piece.begin(), n.piece.end()), n.piece.end());
      layers[i] = seam_layer(n, cell_points);
    }
    const double eps = surface_.eps();
    keep_locations([&](const Node& n) { return layers[static_cast<std::size_t>(&n - nodes_.data())]; },
                   [&](const std::vector<Vec3>& layer, const std::vector<Vec3>& reference) {
                     return same_points(PointCloud{layer, {}}, PointCloud{reference, {}}, eps) ? 0.0
                                                                                              : std::numeric_limits<double>::infinity();
                   },
                   0.0);
    class_misfit_.assign(class_nodes_.size(), 0.0);
  }

  // The points of `n`'s docker piece within eps of its seam, in the non-terminal's frame: where
  // the docker meets the rest of the model. A docker taken from one location fits another when
  // the two layers sample the same cross-section. Only cells whose cube can reach the seam are
  // looked at: band cells, and docker cells near a plane seam (it reaches past the band) or next
  // to a band cell (voxel faces lie in the band).
  std::vector<Vec3> seam_layer(const Node& n, const std::vector<std::vector<std::uint32_t>>& cell_points) const {
    const double eps = surface_.eps();
    const double cell_reach = eps * (1.0 + 0.5 * std::sqrt(3.0));
    const SeamSurface& seam = class_seam_[n.klass];
    std::vector<std::uint32_t> cells = n.site;
    if (seam.kind == SeamSurface::Kind::plane) {
      for (std::uint32_t c : n.docker)
        if (seam.near(n.frame_inverse.apply(surface_.centre(c)), cell_reach)) cells.push_back(c);
    } else {
      for (std::uint32_t c : n.site)
        for (std::uint32_t neighbour : surface_.neighbours(c))
          if (std::binary_search(n.docker.begin(), n.docker.end(), neighbour)) cells.push_back(neighbour);
    }
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    std::vector<Vec3> layer;
    for (std::uint32_t c : cells)
      for (std::uint32_t p : cell_points[c]) {
        if (!std::binary_search(n.piece.begin(), n.piece.end(), p)) continue;  // a band point beyond the seam
        const Vec3 own = n.frame_inverse.apply(cloud_->positions[p]);
        if (seam.near(own, eps)) layer.push_back(own);
      }
    return layer;
  }

  // A docker cut at one location must fit the hole of every other location: the seam curve of
  // each location, moved into the non-terminal's frame, must be that of its reference location
  // (keep_fitting_locations, within kSeamFitFraction of eps). Records each class's largest misfit.
  void check_fit() {
    const EdgeUsers users = edge_users(cut_);
    std::vector<char> inside(cut_.triangles.size(), 0);
    auto curve = [&](const Node& n) {
      for (std::uint32_t t : n.piece) inside[t] = 1;
      std::vector<Segment> segments = seam_segments(cut_, users, n.piece, inside);
      for (std::uint32_t t : n.piece) inside[t] = 0;
      return in_frame(std::move(segments), n);
    };
    class_misfit_ = keep_fitting_locations(curve, kSeamFitFraction * surface_.eps());
  }

  // The cuts split triangles along whole voxel planes; fragments of one exemplar triangle that
  // lie in the same kept dockers are joined and re-triangulated, so pieces only gain triangles
  // along their seams.
  void join_fragments() {
    std::vector<std::vector<std::uint32_t>> holders(cut_.triangles.size());  // kept nodes holding each triangle
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      if (!nodes_[i].kept) nodes_[i].piece.clear();
      for (std::uint32_t t : nodes_[i].piece) holders[t].push_back(static_cast<std::uint32_t>(i));
    }
    std::map<std::vector<std::uint32_t>, std::uint32_t> ids;
    std::vector<std::uint32_t> label(cut_.triangles.size());
    for (std::size_t t = 0; t < label.size(); ++t)
      label[t] = ids.emplace(holders[t], static_cast<std::uint32_t>(ids.size())).first->second;
    std::vector<char> corners(cut_.positions.size(), 0);
    std::fill(corners.begin(), corners.begin() + static_cast<std::ptrdiff_t>(mesh_.positions.size()), 1);
    MergedFragments merged = merge_fragments(cut_, origin_, label, corners, {.moved_distance = snap_distance()});
    std::vector<std::uint32_t> origin(merged.mesh.triangles.size());
    for (Node& n : nodes_) n.piece.clear();
    for (std::uint32_t t = 0; t < merged.mesh.triangles.size(); ++t) {
      const std::uint32_t from = merged.representative[t];
      origin[t] = origin_[from];
      for (std::uint32_t i : holders[from]) nodes_[i].piece.push_back(t);
    }
    cut_ = std::move(merged.mesh);
    origin_ = std::move(origin);
  }

  void count_sites(ContextFreeStats& stats) const {
    for (const Relation& rel : relations_) {
      if (nodes_[rel.from].kept && nodes_[rel.to].kept)
        ++stats.sites_used;
      else
        ++stats.sites_without_fit;
    }
    for (const Node& n : nodes_) {
      if (!n.kept || n.aligned_by == 0.0) continue;
      ++stats.locations_aligned;
      stats.largest_alignment = std::max(stats.largest_alignment, n.aligned_by);
    }
  }

  // Parent of each node: the smallest kept docker holding most of its band and docker, and
  // every triangle of its piece (so the parent's terminal and the child's piece add up).
  void build_tree() {
    const std::size_t n = surface_.cell_count();
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < nodes_.size(); ++i)
      if (nodes_[i].kept) order.push_back(i);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return nodes_[a].docker.size() < nodes_[b].docker.size(); });
    for (std::size_t a_index = 0; a_index < order.size(); ++a_index) {
      const std::size_t a = order[a_index];
      const std::vector<char> docker = mask_of(nodes_[a].docker, n);
      for (std::size_t c_index = 0; c_index < a_index; ++c_index) {
        const std::size_t c = order[c_index];
        Node& child = nodes_[c];
        if (child.parent != kNone || child.docker.size() >= nodes_[a].docker.size()) continue;
        if (share_inside(child.site, docker) >= 0.9 && share_inside(child.docker, docker) >= 0.9 &&
            std::includes(nodes_[a].piece.begin(), nodes_[a].piece.end(), child.piece.begin(), child.piece.end()))
          child.parent = a;
      }
    }
    for (std::size_t i : order) {
      if (nodes_[i].parent != kNone)
        nodes_[nodes_[i].parent].children.push_back(i);
      else
        roots_.push_back(i);
    }
  }

  // Two sites conflict when their sites or dockers share a cell.
  static bool clash(const Node& a, const Node& b) {
    return share_a_cell(a.site, b.site) || share_a_cell(a.docker, b.docker) || share_a_cell(a.site, b.docker) ||
           share_a_cell(a.docker, b.site);
  }

  // The triangles (points of a cloud) of `node`'s piece (kNone: the whole cut model or cloud)
  // outside the pieces of `children`, ascending.
  std::vector<std::uint32_t> remaining(std::size_t node, const std::vector<std::size_t>& children) const {
    std::vector<std::uint32_t> taken;
    for (std::size_t c : children) taken.insert(taken.end(), nodes_[c].piece.begin(), nodes_[c].piece.end());
    std::sort(taken.begin(), taken.end());
    std::vector<std::uint32_t> own;
    if (node == kNone) {
      own.resize(cloud_ ? cloud_->positions.size() : cut_.triangles.size());
      std::iota(own.begin(), own.end(), 0u);
    } else {
      own = nodes_[node].piece;
    }
    std::vector<std::uint32_t> rest;
    std::set_difference(own.begin(), own.end(), taken.begin(), taken.end(), std::back_inserter(rest));
    return rest;
  }

  // Terminal geometry of `node` (kNone: the whole model) without the dockers of `children`, in
  // model coordinates, each triangle with its exemplar triangle's material.
  TriangleMesh remainder(std::size_t node, const std::vector<std::size_t>& children) const {
    // The remaining triangles, renumbered, re-triangulated with only the vertices that the
    // exemplar's corners and the terminal's own border need; then each flat face as a whole
    // (where a whole face cannot be, it keeps the first pass's triangles).
    TriangleMesh part;
    std::vector<std::uint32_t> origin;
    std::vector<char> corners;
    std::unordered_map<std::uint32_t, std::uint32_t> renumbered;
    for (std::uint32_t t : remaining(node, children)) {
      Triangle tri;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = cut_.triangles[t][k];
        const auto [at, added] = renumbered.emplace(v, static_cast<std::uint32_t>(part.positions.size()));
        if (added) {
          part.positions.push_back(cut_.positions[v]);
          corners.push_back(v < mesh_.positions.size() ? 1 : 0);
        }
        tri[k] = at->second;
      }
      part.triangles.push_back(tri);
      if (cut_.has_materials()) part.materials.push_back(cut_.materials[t]);
      origin.push_back(origin_[t]);
    }
    const TriangleMesh merged =
        merge_fragments(part, origin, std::vector<std::uint32_t>(origin.size(), 0), corners,
                        {.straighten_open_borders = true, .moved_distance = snap_distance()})
            .mesh;
    return merge_flat_faces(without_unused_vertices(merged),
                            {.straighten_open_borders = true, .moved_distance = snap_distance()});
  }

  // The production of `node` (kNone: the axiom) with the given children; children must have
  // their own productions already (their dockers are smaller, so they are built first).
  ShapeProduction production(std::size_t node, const std::vector<std::size_t>& children) const {
    ShapeProduction p;
    const RigidTransform to_frame = node == kNone ? RigidTransform{} : nodes_[node].frame.inverse();
    p.lhs = node == kNone ? kNoProduction : class_index_[nodes_[node].klass];
    if (cloud_) {
      p.terminal_source_points = remaining(node, children);
      p.terminal_points = transformed(subcloud(*cloud_, p.terminal_source_points), to_frame);
    } else {
      p.terminal = transformed(remainder(node, children), to_frame);
    }
    p.source_site = node == kNone ? 0 : node;
    p.source_frame = node == kNone ? RigidTransform{} : nodes_[node].frame;
    for (std::size_t c : children)
      p.children.push_back({class_index_[nodes_[c].klass], to_frame.after(nodes_[c].frame), nodes_[c].first_production});
    return p;
  }

  // Size of a piece: its area (model units^2), or for a point cloud its number of points.
  double piece_size(const std::vector<std::uint32_t>& piece) const {
    if (cloud_) return static_cast<double>(piece.size());
    double area = 0.0;
    for (std::uint32_t t : piece) area += 0.5 * cut_.area_vector(t).norm();
    return area;
  }

  void make_productions(ContextFreeGrammar& grammar, ContextFreeStats& stats) {
    // Non-terminals that survived, indexed densely (named once the unreachable ones are gone).
    class_index_.assign(class_nodes_.size(), kNone);
    for (std::size_t k = 0; k < class_nodes_.size(); ++k) {
      std::size_t kept = 0;
      for (std::size_t i : class_nodes_[k]) kept += nodes_[i].kept ? 1 : 0;
      if (kept == 0) continue;
      class_index_[k] = grammar.nonterminals.size();
      ShapeNonterminal nt;
      nt.seam = class_seam_[k];
      nt.sites = kept;
      nt.seam_misfit = class_misfit_[k];
      grammar.nonterminals.push_back(nt);
    }
    auto kept_only = [&](const std::vector<std::size_t>& list) {
      std::vector<std::size_t> out;
      for (std::size_t c : list)
        if (nodes_[c].kept) out.push_back(c);
      return out;
    };
    std::vector<std::size_t> order = kept_only([&] {
      std::vector<std::size_t> all(nodes_.size());
      std::iota(all.begin(), all.end(), 0);
      return all;
    }());
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return nodes_[a].docker.size() < nodes_[b].docker.size(); });
    Random random(options_.seed);
    docker_area_.assign(nodes_.size(), 0.0);
    // A node's candidate children: its kept children and, unfolded one level, theirs.
    auto unfolded = [&](const std::vector<std::size_t>& children) {
      return unfold_one_level(
          children, [&](std::size_t c) { return kept_only(nodes_[c].children); },
          [&](std::size_t a, std::size_t b) { return clash(nodes_[a], nodes_[b]); });
    };
    for (std::size_t i : order) {
      const UnfoldedChildren candidates = unfolded(kept_only(nodes_[i].children));
      docker_area_[i] = piece_size(nodes_[i].piece);
      // The sets are drawn in order (one random sequence); their productions are built in parallel.
      const std::vector<std::vector<std::size_t>> sets =
          random_independent_sets(candidates, options_.independent_set_trials, random);
      std::vector<ShapeProduction> built(sets.size());
      tbb::parallel_for(std::size_t(0), sets.size(), [&](std::size_t k) { built[k] = production(i, sets[k]); });
      for (std::size_t k = 0; k < sets.size(); ++k) {
        const std::vector<std::size_t>& set = sets[k];
        ShapeProduction& p = built[k];
        if (!adds_up(p, set, docker_area_[i])) continue;
        if (opens_holes(p)) {
          ++stats.productions_with_holes;
          continue;
        }
        std::size_t index = grammar.productions.size();
        for (std::size_t q = 0; q < grammar.productions.size() && index == grammar.productions.size(); ++q)
          if (same_production(grammar.productions[q], p, surface_.eps())) index = q;
        if (nodes_[i].first_production == kNoProduction) nodes_[i].first_production = index;
        if (index == grammar.productions.size()) grammar.productions.push_back(std::move(p));
      }
      if (nodes_[i].first_production == kNoProduction) nodes_[i].kept = false;
    }
    // The axiom: of the roots' random independent sets whose pieces add up to the model, the
    // one from which the most non-terminals can be reached, of those the one whose own
    // productions (the exemplar rebuilt) name the most non-terminals (the first such in trial
    // order): of two locations of a non-terminal whose swaps move the whole model, the one whose
    // docker holds the sites below it (the Hochhaus Asemwald's slab with its windows), so that
    // its variation stays in place once the other's alternative goes. Without such a set, the
    // whole model as one terminal (built only then: merging its flat faces costs as much as the
    // model).
    const UnfoldedChildren roots = unfolded(kept_only(roots_));
    std::size_t most_reached = 0, most_rebuilt = 0;
    for (const auto& set : random_independent_sets(roots, options_.independent_set_trials, random)) {
      std::vector<std::size_t> starts;
      for (std::size_t c : set) starts.push_back(class_index_[nodes_[c].klass]);
      const std::vector<char> reachable = reachable_nonterminals(grammar, starts);
      const auto reached = static_cast<std::size_t>(std::count(reachable.begin(), reachable.end(), 1));
      if (reached == 0 || reached < most_reached) continue;
      const std::size_t rebuilt = nonterminals_rebuilt(grammar, set);
      if (reached == most_reached && rebuilt <= most_rebuilt) continue;
      ShapeProduction axiom = production(kNone, set);
      if (!adds_up(axiom, set, cloud_ ? static_cast<double>(cloud_->positions.size()) : mesh_.area()) || opens_holes(axiom))
        continue;
      grammar.axiom = std::move(axiom);
      most_reached = reached;
      most_rebuilt = rebuilt;
    }
    if (most_reached == 0) grammar.axiom = production(kNone, {});
    if (opens_holes(grammar.axiom)) {  // even the exemplar rebuilt from its pieces would have holes
      grammar = {};
      stats.axiom_with_holes = true;
    }
    if (!grammar.empty())
      stats.productions_moving_the_model =
          drop_alternatives_moving_the_model(grammar, swap_motions(grammar.nonterminals.size()));
    stats.unreachable_nonterminals = drop_unreachable_nonterminals(grammar);
  }

  // How many non-terminals the exemplar's own productions name below the nodes `set`: their
  // first productions, then the original productions of those productions' child slots.
  std::size_t nonterminals_rebuilt(const ContextFreeGrammar& grammar, const std::vector<std::size_t>& set) const {
    std::vector<char> named(grammar.nonterminals.size(), 0);
    std::vector<std::size_t> pending;
    for (std::size_t c : set) pending.push_back(nodes_[c].first_production);
    std::vector<char> visited(grammar.productions.size(), 0);
    while (!pending.empty()) {
      const std::size_t p = pending.back();
      pending.pop_back();
      if (p >= grammar.productions.size() || visited[p]) continue;
      visited[p] = 1;
      named[grammar.productions[p].lhs] = 1;
      for (const ChildSlot& slot : grammar.productions[p].children) pending.push_back(slot.original_production);
    }
    return static_cast<std::size_t>(std::count(named.begin(), named.end(), 1));
  }

  // Whether `motion` carries the rest of the model outside `from`'s docker and band onto the
  // surface outside `to`'s docker (up to 1 % of its cells, tested on at most about 5,000 of them).
  bool rest_maps_onto(const Node& from, const Node& to, const RigidTransform& motion) const {
    std::vector<char> skip = mask_of(from.site, surface_.cell_count());
    for (std::uint32_t c : from.docker) skip[c] = 1;
    const std::vector<char> in_docker = mask_of(to.docker, surface_.cell_count());
    const std::size_t rest = surface_.cell_count() - static_cast<std::size_t>(std::count(skip.begin(), skip.end(), 1));
    const std::size_t stride = std::max<std::size_t>(1, rest / 5000);
    std::size_t tested = 0, missed = 0, seen = 0;
    for (std::uint32_t c = 0; c < surface_.cell_count(); ++c) {
      if (skip[c] || seen++ % stride != 0) continue;
      ++tested;
      const std::int64_t hit = nearest_cell(surface_, motion.apply(surface_.centre(c)));
      if (hit < 0 || in_docker[static_cast<std::uint32_t>(hit)]) ++missed;
      if (missed * 100 > rest / stride + 1) return false;
    }
    return missed * 100 <= tested;
  }

  // Per non-terminal: whether its kept locations, two or more, each have the rest of the model
  // (outside docker and band) where the motion from the first location carries the first's rest,
  // both ways. Then a docker cut at one location and put at another rebuilds the whole exemplar
  // moved by that motion: no variation (a gear's tooth-wide strip that a translation repeats);
  // in place when every such motion maps the model's bounding box onto itself within eps.
  std::vector<SwapMotion> swap_motions(std::size_t nonterminal_count) const {
    std::vector<SwapMotion> swaps(nonterminal_count, SwapMotion::none);
    const BoundingBox box = cloud_ ? cloud_->bounds() : mesh_.bounds();
    auto keeps_box = [&](const RigidTransform& motion) {
      BoundingBox moved;
      for (int corner = 0; corner < 8; ++corner) moved.add(motion.apply(box.corner(corner)));
      return std::max((moved.min - box.min).cwiseAbs().maxCoeff(), (moved.max - box.max).cwiseAbs().maxCoeff()) <=
             surface_.eps();
    };
    for (std::size_t k = 0; k < class_nodes_.size(); ++k) {
      if (class_index_[k] == kNone) continue;
      std::vector<std::size_t> kept;
      for (std::size_t i : class_nodes_[k])
        if (nodes_[i].kept) kept.push_back(i);
      if (kept.size() < 2) continue;
      const Node& first = nodes_[kept.front()];
      bool moves = true, in_place = true;
      for (std::size_t i = 1; i < kept.size() && moves; ++i) {
        const Node& other = nodes_[kept[i]];
        const RigidTransform motion = other.frame.after(first.frame_inverse);
        moves = rest_maps_onto(first, other, motion) && rest_maps_onto(other, first, motion.inverse());
        in_place = in_place && keeps_box(motion);
      }
      if (moves) swaps[class_index_[k]] = in_place ? SwapMotion::in_place : SwapMotion::elsewhere;
    }
    return swaps;
  }

  // Whether `p`'s terminal holds a triangle that cleaning drops while the exemplar is closed: it
  // would open a hole in every result (verify requires closed results of closed exemplars).
  bool opens_holes(const ShapeProduction& p) const { return exemplar_closed_ && has_degenerate_triangle(p.terminal); }

  // The terminal and the children's dockers make up the parent's docker (area within 0.1 %, or
  // every point): a cut that does not separate pieces cleanly is not used.
  bool adds_up(const ShapeProduction& p, const std::vector<std::size_t>& children, double docker_area) const {
    double area = cloud_ ? static_cast<double>(p.terminal_points.positions.size()) : p.terminal.area();
    for (std::size_t c : children) area += docker_area_[c];
    return std::abs(area - docker_area) <= 1e-3 * docker_area;
  }

  const VoxelSurface& surface_;
  const TriangleMesh& mesh_;
  const PointCloud* cloud_;  // the exemplar's points when it is a point cloud (then mesh_ is empty)
  const ContextFreeOptions& options_;
  const ProgressCallback& progress_;
  bool exemplar_closed_;
  std::vector<Node> nodes_;
  std::vector<Relation> relations_;
  std::vector<std::vector<std::size_t>> class_nodes_;
  std::vector<SeamSurface> class_seam_;               // per class, in its frame
  std::vector<double> class_misfit_;                  // per class: largest seam misfit of a kept location, model units
  std::vector<std::vector<char>> class_docker_side_;  // per class with a voxel seam: cells on its docker side
  std::vector<SeamFaceIndex> class_face_index_;       // per class: its seam's voxel faces by plane
  TriangleMesh cut_;                                  // the exemplar cut along every kept seam
  std::vector<std::uint32_t> origin_;                 // per triangle of cut_: its exemplar triangle
  std::vector<std::size_t> roots_;
  std::vector<std::size_t> class_index_;  // class -> non-terminal index
  std::vector<double> docker_area_;       // per node: piece_size of its docker
};

}  // namespace

double seam_weld_tolerance(const ContextFreeGrammar& grammar, double eps) {
  double tolerance = kSeamWeldFloorFraction * eps;
  for (const ShapeNonterminal& n : grammar.nonterminals) tolerance = std::max(tolerance, 2.0 * n.seam_misfit);
  return tolerance;
}

ContextFreeGrammar build_context_free_grammar(const PreparedModel& prepared, const DockingSiteResult& sites,
                                              const ContextFreeOptions& options, ContextFreeStats* stats,
                                              const ProgressCallback& progress) {
  ContextFreeStats local;
  Builder builder(prepared, options, progress);
  ContextFreeGrammar grammar = builder.build(sites, local);
  if (stats) *stats = local;
  return grammar;
}

}  // namespace dg
