#include "grammar/context_free.h"

#include "geometry/slab_cut.h"
#include "geometry/submesh.h"
#include "grammar/cell_sets.h"
#include "grammar/random.h"
#include "symmetry/symmetric_region.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <fmt/format.h>
#include <numeric>
#include <optional>
#include <set>

namespace dg {
namespace {

using Cells = std::vector<std::uint32_t>;
constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

double jaccard(const Cells& a, const Cells& b) {
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
  const std::size_t together = a.size() + b.size() - shared;
  return together == 0 ? 1.0 : static_cast<double>(shared) / static_cast<double>(together);
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

struct Plane {
  Vec3 normal = Vec3::UnitX();
  double offset = 0.0;
  double distance(const Vec3& p) const { return normal.dot(p) - offset; }
  Plane moved(const RigidTransform& t) const {
    const Vec3 n = t.apply_direction(normal);
    return {n, n.dot(t.apply(offset * normal))};
  }
};

struct Node {
  Cells site, docker;
  std::size_t klass = kNone;
  RigidTransform frame;  // non-terminal frame -> this location
  Plane seam;            // in model coordinates, normal towards the docker
  bool kept = true;
  std::size_t parent = kNone;
  std::vector<std::size_t> children;
  std::size_t first_production = kNoProduction;
};

struct Relation {
  std::size_t from, to;
  RigidTransform motion;  // frame(to) = motion after frame(from)
};

// Least-squares plane through the band's cell centres, oriented towards the docker; nothing
// when the band is not flat within `flatness` or the docker is not on one side of it.
std::optional<Plane> fit_seam(const VoxelSurface& surface, const Node& node, double flatness) {
  if (node.site.size() < 3) return std::nullopt;
  Vec3 mean = Vec3::Zero();
  for (std::uint32_t c : node.site) mean += surface.centre(c);
  mean /= static_cast<double>(node.site.size());
  Mat3 covariance = Mat3::Zero();
  for (std::uint32_t c : node.site) {
    const Vec3 d = surface.centre(c) - mean;
    covariance += d * d.transpose();
  }
  // A cut across a pipe or a bar is perpendicular to the walls it crosses: prefer the direction
  // the band's surface normals leave out; fall back to the flattest direction of the band.
  Mat3 normals = Mat3::Zero();
  for (std::uint32_t c : node.site)
    for (const CellPlane& p : surface.planes(c)) normals += p.normal * p.normal.transpose();
  const Eigen::SelfAdjointEigenSolver<Mat3> across(normals);
  const Eigen::SelfAdjointEigenSolver<Mat3> solver(covariance);
  const bool walls_decide = across.eigenvalues()(0) < 0.05 * across.eigenvalues()(1);
  Plane plane{(walls_decide ? across.eigenvectors().col(0) : solver.eigenvectors().col(0)).normalized(), 0.0};
  plane.offset = plane.normal.dot(mean);
  for (std::uint32_t c : node.site)
    if (std::abs(plane.distance(surface.centre(c))) > flatness) return std::nullopt;
  return plane;
}

// Orients `plane` so the docker cells next to the band lie on its positive side; false when
// they do not lie mostly on one side.
bool orient_towards_docker(const VoxelSurface& surface, const Node& node, const std::vector<char>& site_mask, Plane& plane) {
  std::size_t positive = 0, negative = 0;
  for (std::uint32_t c : node.docker) {
    bool next_to_band = false;
    for (std::uint32_t n : surface.neighbours(c)) next_to_band = next_to_band || site_mask[n];
    if (!next_to_band) continue;
    const double d = plane.distance(surface.centre(c));
    if (d > 0) ++positive;
    if (d < 0) ++negative;
  }
  const std::size_t total = positive + negative;
  if (total == 0) return false;
  if (negative > positive) {
    plane.normal = -plane.normal;
    plane.offset = -plane.offset;
    std::swap(positive, negative);
  }
  return positive >= 0.8 * static_cast<double>(total);
}

// Random maximal independent sets of the conflict graph over `items` (paper: a random start,
// then random nodes added while they conflict with none chosen), distinct, trial order.
std::vector<std::vector<std::size_t>> independent_sets(const std::vector<std::size_t>& items,
                                                       const std::vector<std::vector<char>>& conflict, int trials,
                                                       Random& random) {
  std::vector<std::vector<std::size_t>> sets;
  if (items.empty()) return {{}};
  std::set<std::vector<std::size_t>> seen;
  for (int trial = 0; trial < trials; ++trial) {
    std::vector<std::size_t> order(items.size());
    std::iota(order.begin(), order.end(), 0);
    for (std::size_t i = order.size(); i > 1; --i)
      std::swap(order[i - 1], order[static_cast<std::size_t>(random.uniform() * static_cast<double>(i))]);
    const std::size_t start = static_cast<std::size_t>(trial) % items.size();
    std::rotate(order.begin(), std::find(order.begin(), order.end(), start), order.end());
    std::vector<std::size_t> chosen;
    for (std::size_t i : order) {
      bool free = true;
      for (std::size_t j : chosen) free = free && !conflict[i][j];
      if (free) chosen.push_back(i);
    }
    std::vector<std::size_t> set;
    for (std::size_t i : chosen) set.push_back(items[i]);
    std::sort(set.begin(), set.end());
    if (seen.insert(set).second) sets.push_back(set);
  }
  return sets;
}

// Equal up to `tolerance` (model units): same left side, same terminal triangles (compared by
// count, area and bounding box) and the same child slots with the same exemplar productions.
bool same_production(const ShapeProduction& a, const ShapeProduction& b, double tolerance) {
  if (a.lhs != b.lhs || a.terminal.triangles.size() != b.terminal.triangles.size() || a.children.size() != b.children.size())
    return false;
  if (std::abs(a.terminal.area() - b.terminal.area()) > tolerance * tolerance) return false;
  if (!a.terminal.triangles.empty()) {
    const BoundingBox ba = a.terminal.bounds(), bb = b.terminal.bounds();
    if ((ba.min - bb.min).norm() > tolerance || (ba.max - bb.max).norm() > tolerance) return false;
  }
  for (std::size_t i = 0; i < a.children.size(); ++i) {
    const ChildSlot &x = a.children[i], &y = b.children[i];
    if (x.nonterminal != y.nonterminal || x.original_production != y.original_production ||
        !same_motion(x.placement, y.placement, Vec3::Zero(), tolerance))
      return false;
  }
  return true;
}

class Builder {
 public:
  Builder(const PreparedModel& prepared, const ContextFreeOptions& options)
      : surface_(prepared.surface), mesh_(prepared.model.mesh), options_(options) {}

  ContextFreeGrammar build(const DockingSiteResult& sites, ContextFreeStats& stats) {
    collect_nodes(sites, stats);
    assign_classes();
    fit_seams(stats);
    build_tree();
    ContextFreeGrammar grammar;
    make_productions(grammar);
    stats.nodes = 0;
    for (const Node& n : nodes_) stats.nodes += n.kept ? 1 : 0;
    return grammar;
  }

 private:
  std::size_t add_node(const Cells& site, const Cells& docker) {
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      const Node& n = nodes_[i];
      const double size_ratio = static_cast<double>(std::min(n.docker.size(), docker.size())) /
                                static_cast<double>(std::max<std::size_t>(1, std::max(n.docker.size(), docker.size())));
      if (size_ratio < 0.8) continue;
      if (jaccard(n.docker, docker) >= 0.8 && jaccard(n.site, site) >= 0.5) return i;
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
      const std::size_t a = add_node(s.site, s.docker);
      const std::size_t b = add_node(s.secondary_site, s.secondary_docker);
      if (a == kNone || b == kNone || a == b) continue;
      relations_.push_back({a, b, s.transform});
    }
  }

  // Non-terminals: nodes connected by site motions, frames composed along a spanning tree.
  void assign_classes() {
    std::vector<std::vector<std::pair<std::size_t, RigidTransform>>> edges(nodes_.size());
    for (const Relation& r : relations_) {
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
    for (Node& n : nodes_) n.kept = n.klass != kNone;
  }

  void fit_seams(ContextFreeStats& stats) {
    const double flatness = 2.0 * surface_.eps();
    class_seam_.assign(class_nodes_.size(), std::nullopt);
    for (std::size_t k = 0; k < class_nodes_.size(); ++k) {
      const Node& root = nodes_[class_nodes_[k].front()];
      std::optional<Plane> plane = fit_seam(surface_, root, flatness);
      if (plane && !orient_towards_docker(surface_, root, mask_of(root.site, surface_.cell_count()), *plane)) plane.reset();
      if (!plane) {
        for (std::size_t i : class_nodes_[k]) nodes_[i].kept = false;
        continue;
      }
      class_seam_[k] = plane;
      for (std::size_t i : class_nodes_[k]) {
        Node& n = nodes_[i];
        n.seam = plane->moved(n.frame);
        bool flat = true;
        for (std::uint32_t c : n.site) flat = flat && std::abs(n.seam.distance(surface_.centre(c))) <= 1.5 * flatness;
        Plane check = n.seam;
        n.kept = flat && orient_towards_docker(surface_, n, mask_of(n.site, surface_.cell_count()), check) &&
                 check.normal.dot(n.seam.normal) > 0;
      }
    }
    // A non-terminal needs at least two locations to offer an alternative.
    for (auto& members : class_nodes_) {
      std::size_t kept = 0;
      for (std::size_t i : members) kept += nodes_[i].kept ? 1 : 0;
      if (kept < 2)
        for (std::size_t i : members) nodes_[i].kept = false;
    }
    for (std::size_t r = 0; r < relations_.size(); ++r) {
      const Relation& rel = relations_[r];
      if (nodes_[rel.from].kept && nodes_[rel.to].kept)
        ++stats.sites_used;
      else if (!class_seam_[nodes_[rel.from].klass])
        ++stats.sites_not_planar;
    }
  }

  // Parent of each node: the smallest kept docker holding most of its band and docker.
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
        if (share_inside(child.site, docker) >= 0.9 && share_inside(child.docker, docker) >= 0.9) child.parent = a;
      }
    }
    for (std::size_t i : order) {
      if (nodes_[i].parent != kNone)
        nodes_[nodes_[i].parent].children.push_back(i);
      else
        roots_.push_back(i);
    }
  }

  std::vector<std::vector<char>> conflicts(const std::vector<std::size_t>& items) const {
    std::vector<std::vector<char>> conflict(items.size(), std::vector<char>(items.size(), 0));
    for (std::size_t i = 0; i < items.size(); ++i)
      for (std::size_t j = i + 1; j < items.size(); ++j) {
        const Node& a = nodes_[items[i]];
        const Node& b = nodes_[items[j]];
        const bool clash = share_a_cell(a.site, b.site) || share_a_cell(a.docker, b.docker) ||
                           share_a_cell(a.site, b.docker) || share_a_cell(a.docker, b.site);
        conflict[i][j] = conflict[j][i] = clash;
      }
    return conflict;
  }

  // Whether triangle `t` of `mesh` (cut along the node's seam) belongs to the node's docker.
  bool in_docker(const Node& node, const std::vector<char>& docker, const std::vector<char>& site, const TriangleMesh& mesh,
                 std::size_t t) const {
    const auto corners = mesh.corners(t);
    const Vec3 centroid = (corners[0] + corners[1] + corners[2]) / 3.0;
    const std::int64_t cell = nearest_cell(surface_, centroid);
    if (cell < 0) return false;
    if (docker[static_cast<std::size_t>(cell)]) return true;
    return site[static_cast<std::size_t>(cell)] && node.seam.distance(centroid) > 0;
  }

  // Terminal geometry of `node` (kNone: the whole model) without the dockers of `children`,
  // in model coordinates.
  TriangleMesh remainder(std::size_t node, const std::vector<std::size_t>& children) const {
    const std::size_t n = surface_.cell_count();
    const double tolerance = 1e-6 * surface_.eps();
    TriangleMesh cut = mesh_;
    std::vector<std::size_t> involved = children;
    if (node != kNone) involved.push_back(node);
    for (std::size_t i : involved) cut = cut_along_planes(cut, nodes_[i].seam.normal, {nodes_[i].seam.offset}, tolerance);
    std::vector<char> keep(cut.triangles.size(), node == kNone ? 1 : 0);
    if (node != kNone) {
      const std::vector<char> docker = mask_of(nodes_[node].docker, n), site = mask_of(nodes_[node].site, n);
      for (std::size_t t = 0; t < cut.triangles.size(); ++t) keep[t] = in_docker(nodes_[node], docker, site, cut, t);
    }
    for (std::size_t c : children) {
      const std::vector<char> docker = mask_of(nodes_[c].docker, n), site = mask_of(nodes_[c].site, n);
      for (std::size_t t = 0; t < cut.triangles.size(); ++t)
        if (keep[t] && in_docker(nodes_[c], docker, site, cut, t)) keep[t] = 0;
    }
    std::vector<std::size_t> triangles;
    for (std::size_t t = 0; t < keep.size(); ++t)
      if (keep[t]) triangles.push_back(t);
    return submesh(cut, triangles);
  }

  // The production of `node` (kNone: the axiom) with the given children; children must have
  // their own productions already (their dockers are smaller, so they are built first).
  ShapeProduction production(std::size_t node, const std::vector<std::size_t>& children) const {
    ShapeProduction p;
    const RigidTransform to_frame = node == kNone ? RigidTransform{} : nodes_[node].frame.inverse();
    p.lhs = node == kNone ? kNoProduction : class_index_[nodes_[node].klass];
    p.terminal = transformed(remainder(node, children), to_frame);
    p.source_site = node == kNone ? 0 : node;
    for (std::size_t c : children)
      p.children.push_back({class_index_[nodes_[c].klass], to_frame.after(nodes_[c].frame), nodes_[c].first_production});
    return p;
  }

  void make_productions(ContextFreeGrammar& grammar) {
    // Non-terminals that survived, numbered densely.
    class_index_.assign(class_nodes_.size(), kNone);
    for (std::size_t k = 0; k < class_nodes_.size(); ++k) {
      std::size_t kept = 0;
      for (std::size_t i : class_nodes_[k]) kept += nodes_[i].kept ? 1 : 0;
      if (kept == 0) continue;
      class_index_[k] = grammar.nonterminals.size();
      ShapeNonterminal nt;
      nt.name = fmt::format("N{}", grammar.nonterminals.size() + 1);
      nt.seam_normal = class_seam_[k]->normal;
      nt.seam_offset = class_seam_[k]->offset;
      nt.sites = kept;
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
    for (std::size_t i : order) {
      const std::vector<std::size_t> children = kept_only(nodes_[i].children);
      docker_area_[i] = remainder(i, {}).area();
      for (const auto& set : independent_sets(children, conflicts(children), options_.independent_set_trials, random)) {
        ShapeProduction p = production(i, set);
        if (!adds_up(p, set, docker_area_[i])) continue;
        std::size_t index = grammar.productions.size();
        for (std::size_t q = 0; q < grammar.productions.size() && index == grammar.productions.size(); ++q)
          if (same_production(grammar.productions[q], p, surface_.eps())) index = q;
        if (nodes_[i].first_production == kNoProduction) nodes_[i].first_production = index;
        if (index == grammar.productions.size()) grammar.productions.push_back(std::move(p));
      }
      if (nodes_[i].first_production == kNoProduction) nodes_[i].kept = false;
    }
    const std::vector<std::size_t> roots = kept_only(roots_);
    const std::vector<std::size_t> axiom_children = independent_sets(roots, conflicts(roots), 1, random).front();
    grammar.axiom = production(kNone, axiom_children);
    if (!adds_up(grammar.axiom, axiom_children, mesh_.area())) grammar.axiom = production(kNone, {});
  }

  // The terminal and the children's dockers make up the parent's docker (area within 0.1 %):
  // a cut that does not separate pieces cleanly is not used.
  bool adds_up(const ShapeProduction& p, const std::vector<std::size_t>& children, double docker_area) const {
    double area = p.terminal.area();
    for (std::size_t c : children) area += docker_area_[c];
    return std::abs(area - docker_area) <= 1e-3 * docker_area;
  }

  const VoxelSurface& surface_;
  const TriangleMesh& mesh_;
  const ContextFreeOptions& options_;
  std::vector<Node> nodes_;
  std::vector<Relation> relations_;
  std::vector<std::vector<std::size_t>> class_nodes_;
  std::vector<std::optional<Plane>> class_seam_;
  std::vector<std::size_t> roots_;
  std::vector<std::size_t> class_index_;  // class -> non-terminal index
  std::vector<double> docker_area_;  // per node, model units^2
};

}  // namespace

ContextFreeGrammar build_context_free_grammar(const PreparedModel& prepared, const DockingSiteResult& sites,
                                              const ContextFreeOptions& options, ContextFreeStats* stats) {
  ContextFreeStats local;
  Builder builder(prepared, options);
  ContextFreeGrammar grammar = builder.build(sites, local);
  if (stats) *stats = local;
  return grammar;
}

}  // namespace dg
