#include "grammar/inference_clusters.h"

#include "grammar/inference_mean_shift.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <set>
#include <unordered_map>

namespace dg {

namespace {

struct Pair {
  std::size_t from = 0, to = 0;
  TurtleTransform t{};
  double world_distance = 0;
};

// Which coordinates of (alpha, d, s, beta) a space leaves free to change linearly with m.
struct Space {
  std::array<bool, 4> free{};
};

bool is_angle(int c) { return c == 0 || c == 3; }

// Directed pairs between each node and its nearest nodes of the same type.
std::vector<Pair> neighbour_pairs(const std::vector<SceneNode>& nodes, const std::vector<std::size_t>& members, int k) {
  std::set<std::pair<std::size_t, std::size_t>> seen;
  std::vector<Pair> pairs;
  std::vector<std::pair<double, std::size_t>> distances;
  for (std::size_t i : members) {
    distances.clear();
    for (std::size_t j : members)
      if (j != i) distances.emplace_back((nodes[j].frame.position - nodes[i].frame.position).squaredNorm(), j);
    const std::size_t take = std::min<std::size_t>(static_cast<std::size_t>(std::max(k, 1)), distances.size());
    std::partial_sort(distances.begin(), distances.begin() + static_cast<std::ptrdiff_t>(take), distances.end());
    for (std::size_t n = 0; n < take; ++n) {
      const std::size_t j = distances[n].second;
      for (auto [a, b] : {std::pair{i, j}, std::pair{j, i}})
        if (seen.emplace(a, b).second)
          pairs.push_back(Pair{a, b, relative_transform(nodes[a].exit, nodes[b].frame),
                               (nodes[b].frame.position - nodes[a].exit.position).norm()});
    }
  }
  return pairs;
}

// Links the pairs of one cluster into disjoint chains (nearest pairs first, no branching, no
// cycles); returns the chains as lists of pair indices in order.
std::vector<std::vector<std::size_t>> link_chains(const std::vector<Pair>& pairs, std::vector<std::size_t> cluster) {
  std::sort(cluster.begin(), cluster.end(), [&](std::size_t a, std::size_t b) {
    if (pairs[a].world_distance != pairs[b].world_distance) return pairs[a].world_distance < pairs[b].world_distance;
    return std::pair{pairs[a].from, pairs[a].to} < std::pair{pairs[b].from, pairs[b].to};
  });
  std::unordered_map<std::size_t, std::size_t> next, previous, root;
  std::function<std::size_t(std::size_t)> find = [&](std::size_t x) {
    auto it = root.find(x);
    if (it == root.end() || it->second == x) return x;
    const std::size_t r = find(it->second);
    root[x] = r;
    return r;
  };
  for (std::size_t p : cluster) {
    const Pair& pair = pairs[p];
    if (next.count(pair.from) || previous.count(pair.to)) continue;
    if (find(pair.from) == find(pair.to)) continue;
    next[pair.from] = p;
    previous[pair.to] = p;
    root[find(pair.from)] = find(pair.to);
  }
  std::vector<std::size_t> starts;
  for (const auto& [node, p] : next)
    if (!previous.count(node)) starts.push_back(node);
  std::sort(starts.begin(), starts.end());
  std::vector<std::vector<std::size_t>> chains;
  for (std::size_t node : starts) {
    std::vector<std::size_t> chain;
    for (auto it = next.find(node); it != next.end(); it = next.find(pairs[it->second].to)) chain.push_back(it->second);
    chains.push_back(std::move(chain));
  }
  return chains;
}

double coordinate_tolerance(int c, double value, const ClusterOptions& options) {
  if (is_angle(c)) return options.angle_tolerance_deg;
  return options.relative_tolerance * std::max(std::abs(value), c == 1 ? 1e-9 : 1.0);
}

// Cuts chains where a free coordinate stops changing linearly (second difference too large).
std::vector<std::vector<std::size_t>> split_linear(const std::vector<Pair>& pairs, const std::vector<std::vector<std::size_t>>& chains,
                                                   const Space& space, const ClusterOptions& options) {
  std::vector<std::vector<std::size_t>> out;
  for (const auto& chain : chains) {
    std::vector<std::size_t> run;
    for (std::size_t link : chain) {
      bool breaks = false;
      if (run.size() >= 2) {
        const TurtleTransform &a = pairs[run[run.size() - 2]].t, &b = pairs[run.back()].t, &c = pairs[link].t;
        for (int k = 0; k < 4; ++k) {
          if (!space.free[static_cast<std::size_t>(k)]) continue;
          const double step1 = is_angle(k) ? wrap_degrees(b[k] - a[k]) : b[k] - a[k];
          const double step2 = is_angle(k) ? wrap_degrees(c[k] - b[k]) : c[k] - b[k];
          if (std::abs(step2 - step1) > coordinate_tolerance(k, b[k], options)) breaks = true;
        }
      }
      if (breaks) {
        out.push_back(std::move(run));
        run.clear();  // the outlying link is dropped; a new run starts after it
        continue;
      }
      run.push_back(link);
    }
    if (!run.empty()) out.push_back(std::move(run));
  }
  return out;
}

// Fits t(m) = start + slope m to the links of the chains (m = chain length - link index), free
// coordinates linearly and the others as constants; drops chains that deviate, refits once.
bool fit_rule(const std::vector<Pair>& pairs, std::vector<std::vector<std::size_t>>& chains, const Space& space,
              const ClusterOptions& options, TurtleTransform& start, TurtleTransform& slope) {
  for (int round = 0; round < 2; ++round) {
    if (chains.empty()) return false;
    const TurtleTransform reference = pairs[chains.front().front()].t;
    for (int c = 0; c < 4; ++c) {
      double sm = 0, sv = 0, smm = 0, smv = 0, count = 0;
      for (const auto& chain : chains)
        for (std::size_t k = 0; k < chain.size(); ++k) {
          const double m = static_cast<double>(chain.size() + 1 - k);
          double v = pairs[chain[k]].t[c];
          if (is_angle(c)) v = reference[c] + wrap_degrees(v - reference[c]);
          sm += m, sv += v, smm += m * m, smv += m * v, count += 1;
        }
      const double det = count * smm - sm * sm;
      double b = space.free[static_cast<std::size_t>(c)] && det > 1e-12 ? (count * smv - sm * sv) / det : 0;
      if (b != 0) {  // three significant digits, then the start refitted to the rounded slope
        const double unit = std::pow(10.0, std::floor(std::log10(std::abs(b))) - 2);
        b = std::round(b / unit) * unit;
      }
      double a = (sv - b * sm) / count;
      double max_m = 0;
      for (const auto& chain : chains) max_m = std::max(max_m, static_cast<double>(chain.size() + 1));
      if (std::abs(b) * max_m <= coordinate_tolerance(c, a, options) / 2) b = 0, a = sv / count;
      if (b == 0) {  // a constant within the spread of its links from the neutral value is that value (§5.7)
        double spread = 0;
        for (const auto& chain : chains)
          for (std::size_t k = 0; k < chain.size(); ++k) {
            double v = pairs[chain[k]].t[c];
            if (is_angle(c)) v = reference[c] + wrap_degrees(v - reference[c]);
            spread += (v - a) * (v - a);
          }
        spread = std::sqrt(spread / count);
        const double neutral = c == 2 ? 1.0 : 0.0;
        if (c != 1 && std::abs(a - neutral) <= 2 * spread) a = neutral;
      }
      start[c] = is_angle(c) ? wrap_degrees(a) : a;
      slope[c] = b;
    }
    std::vector<std::vector<std::size_t>> kept;
    for (auto& chain : chains) {
      bool fits = true;
      for (std::size_t k = 0; k < chain.size(); ++k) {
        const double m = static_cast<double>(chain.size() + 1 - k);
        for (int c = 0; c < 4; ++c) {
          const double predicted = start[c] + slope[c] * m;
          const double v = pairs[chain[k]].t[c];
          const double error = is_angle(c) ? wrap_degrees(v - predicted) : v - predicted;
          if (std::abs(error) > coordinate_tolerance(c, predicted, options)) fits = false;
        }
      }
      if (fits) kept.push_back(std::move(chain));
    }
    const bool all = kept.size() == chains.size();
    chains = std::move(kept);
    if (all) return !chains.empty();
  }
  return !chains.empty();
}

double closest_distance(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  double best = std::numeric_limits<double>::infinity();
  for (const Vec2& p : a)
    for (const Vec2& q : b) best = std::min(best, (p - q).squaredNorm());
  return std::sqrt(best);
}

struct Scored {
  RuleCandidate candidate;
  std::vector<std::pair<std::size_t, std::size_t>> links;
};

void score(std::vector<Scored>& all, const std::vector<SceneNode>& nodes, double diagonal, const ImportanceWeights& w) {
  double max_n = 0, max_l = 0;
  for (const Scored& s : all) {
    max_n = std::max(max_n, static_cast<double>(s.candidate.absorbed));
    max_l = std::max(max_l, static_cast<double>(s.candidate.absorbed + s.candidate.groups.size()) / static_cast<double>(s.candidate.groups.size()));
  }
  for (Scored& s : all) {
    RuleCandidate& c = s.candidate;
    const double n = static_cast<double>(c.absorbed) / std::max(max_n, 1.0);
    const double l = static_cast<double>(c.absorbed + c.groups.size()) / static_cast<double>(c.groups.size()) / std::max(max_l, 1.0);
    double proximity = 0, similarity = 0;
    const std::size_t stride = std::max<std::size_t>(1, s.links.size() / 512);
    std::size_t used = 0;
    for (std::size_t k = 0; k < s.links.size(); k += stride, ++used) {
      const auto [a, b] = s.links[k];
      proximity += 1 - std::min(1.0, closest_distance(nodes[a].samples, nodes[b].samples) / std::max(diagonal, 1e-12));
      similarity += std::min(nodes[a].similarity, nodes[b].similarity);
    }
    const double h = used ? proximity / static_cast<double>(used) : 0;
    const double phi = used ? similarity / static_cast<double>(used) : 0;
    c.score = w.w_n * n + w.w_h * h + w.w_phi * phi + w.w_l * l;
  }
}

// Complete binary trees of two constant transforms (rule r3/r4) in clusters a and b.
void branching_candidates(const std::vector<Pair>& pairs, const std::vector<std::vector<std::size_t>>& cluster_chains_a,
                          const std::vector<std::vector<std::size_t>>& cluster_chains_b, const std::string& type,
                          std::vector<Scored>& out) {
  std::unordered_map<std::size_t, std::size_t> next_a, next_b;  // node -> pair index
  for (const auto& chain : cluster_chains_a)
    for (std::size_t p : chain) next_a[pairs[p].from] = p;
  for (const auto& chain : cluster_chains_b)
    for (std::size_t p : chain) next_b[pairs[p].from] = p;
  if (next_a.empty() || next_b.empty()) return;
  std::unordered_map<std::size_t, int> depth;
  std::function<int(std::size_t)> depth_of = [&](std::size_t x) -> int {
    if (auto it = depth.find(x); it != depth.end()) return it->second;
    depth[x] = 0;  // guards against cycles
    int d = 0;
    auto ia = next_a.find(x), ib = next_b.find(x);
    if (ia != next_a.end() && ib != next_b.end() && pairs[ia->second].to != pairs[ib->second].to)
      d = 1 + std::min(depth_of(pairs[ia->second].to), depth_of(pairs[ib->second].to));
    depth[x] = d;
    return d;
  };
  std::vector<std::pair<int, std::size_t>> roots;
  for (const auto& [x, p] : next_a)
    if (next_b.count(x) && depth_of(x) >= 1) roots.emplace_back(depth_of(x), x);
  std::sort(roots.begin(), roots.end(), [](const auto& u, const auto& v) { return u.first != v.first ? u.first > v.first : u.second < v.second; });
  std::set<std::size_t> covered;
  Scored result;
  RuleCandidate& c = result.candidate;
  c.branching = true;
  c.child_type = type;
  TurtleTransform sum_a{}, sum_b{};
  double edges = 0;
  const TurtleTransform ref_a = pairs[next_a.begin()->second].t, ref_b = pairs[next_b.begin()->second].t;
  for (const auto& [d, x] : roots) {
    if (covered.count(x)) continue;
    std::vector<std::size_t> tree{x};
    std::vector<std::pair<std::size_t, int>> frontier{{x, d}};
    std::vector<std::pair<std::size_t, std::size_t>> used;
    bool clean = true;
    std::set<std::size_t> inside{x};
    while (!frontier.empty() && clean) {
      const auto [node, level] = frontier.back();
      frontier.pop_back();
      if (level == 0) continue;
      for (const auto* next : {&next_a, &next_b}) {
        const std::size_t p = next->at(node);
        const std::size_t child = pairs[p].to;
        if (covered.count(child) || !inside.insert(child).second) clean = false;
        tree.push_back(child);
        used.emplace_back(node, p);
        frontier.emplace_back(child, level - 1);
      }
    }
    if (!clean) continue;
    covered.insert(tree.begin(), tree.end());
    for (const auto& [node, p] : used) {
      const bool is_a = next_a.at(node) == p;
      TurtleTransform& sum = is_a ? sum_a : sum_b;
      const TurtleTransform& ref = is_a ? ref_a : ref_b;
      for (int k = 0; k < 4; ++k) sum[k] += is_angle(k) ? ref[k] + wrap_degrees(pairs[p].t[k] - ref[k]) : pairs[p].t[k];
      if (is_a) edges += 1;
      result.links.emplace_back(node, pairs[p].to);
    }
    c.groups.push_back(std::move(tree));
    c.counters.push_back(d);
    c.absorbed += c.groups.back().size() - 1;
  }
  if (c.groups.empty() || edges == 0) return;
  for (int k = 0; k < 4; ++k) {
    c.start[k] = sum_a[k] / edges;
    c.second[k] = sum_b[k] / edges;
    if (is_angle(k)) c.start[k] = wrap_degrees(c.start[k]), c.second[k] = wrap_degrees(c.second[k]);
  }
  if (c.second < c.start) std::swap(c.start, c.second);
  out.push_back(std::move(result));
}

ShiftPoint full_space_point(const TurtleTransform& t, double diagonal, const ClusterOptions& options) {
  const double log_d = std::log(std::max(t[1], 1e-9 * std::max(diagonal, 1e-12))) / options.log_distance_bandwidth;
  return {t[0] / options.angle_bandwidth_deg, log_d, std::log(t[2]) / options.log_scale_bandwidth, t[3] / options.angle_bandwidth_deg};
}

// Completes the strongest clusters of the full space: every element is moved by each strong
// cluster's mean transform, and an element of the same type found there (position within 3 %
// of the move, angle and scale within the tolerances) is paired with it, even when it is not
// among the nearest neighbours (crowded drawings, small elements beside large ones).
void add_predicted_pairs(const std::vector<SceneNode>& nodes, const std::vector<std::size_t>& members, double diagonal,
                         const ClusterOptions& options, std::vector<Pair>& pairs) {
  std::vector<ShiftPoint> points;
  for (const Pair& p : pairs) points.push_back(full_space_point(p.t, diagonal, options));
  const double period = 360.0 / options.angle_bandwidth_deg;
  const ShiftClusters clusters = mean_shift(points, 4, {period, 0, 0, period});
  const std::size_t strong = std::min<std::size_t>(clusters.centers.size(), static_cast<std::size_t>(options.max_branch_clusters));
  std::vector<TurtleTransform> means(strong, TurtleTransform{0, 0, 0, 0});
  std::vector<double> counts(strong, 0);
  std::vector<TurtleTransform> reference(strong);
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const int label = clusters.labels[p];
    if (label < 0 || static_cast<std::size_t>(label) >= strong) continue;
    const std::size_t c = static_cast<std::size_t>(label);
    if (counts[c] == 0) reference[c] = pairs[p].t;
    for (int k = 0; k < 4; ++k)
      means[c][k] += is_angle(k) ? reference[c][k] + wrap_degrees(pairs[p].t[k] - reference[c][k]) : pairs[p].t[k];
    counts[c] += 1;
  }
  std::vector<std::size_t> by_x(members);
  std::sort(by_x.begin(), by_x.end(), [&](std::size_t a, std::size_t b) { return nodes[a].frame.position.x() < nodes[b].frame.position.x(); });
  std::set<std::pair<std::size_t, std::size_t>> present;
  for (const Pair& p : pairs) present.emplace(p.from, p.to);
  for (std::size_t c = 0; c < strong; ++c) {
    if (counts[c] < 2) continue;
    TurtleTransform t = means[c];
    for (int k = 0; k < 4; ++k) t[k] /= counts[c];
    for (std::size_t i : members) {
      const InstanceFrame target = apply_transform(nodes[i].exit, t);
      const double radius = 0.03 * t[1] * nodes[i].exit.scale + 1e-6 * diagonal;
      auto it = std::lower_bound(by_x.begin(), by_x.end(), target.position.x() - radius,
                                 [&](std::size_t n, double x) { return nodes[n].frame.position.x() < x; });
      for (; it != by_x.end() && nodes[*it].frame.position.x() <= target.position.x() + radius; ++it) {
        const SceneNode& candidate = nodes[*it];
        if (*it == i || (candidate.frame.position - target.position).norm() > radius) continue;
        if (std::abs(wrap_degrees(candidate.frame.angle_deg - target.angle_deg)) > options.angle_tolerance_deg) continue;
        if (std::abs(candidate.frame.scale / target.scale - 1) > options.relative_tolerance) continue;
        if (!present.emplace(i, *it).second) continue;
        pairs.push_back(Pair{i, *it, relative_transform(nodes[i].exit, candidate.frame),
                             (candidate.frame.position - nodes[i].exit.position).norm()});
      }
    }
  }
}

}  // namespace

std::vector<RuleCandidate> find_rule_candidates(const std::vector<SceneNode>& nodes, double diagonal, const ClusterOptions& options) {
  std::map<std::string, std::vector<std::size_t>> by_type;
  for (std::size_t i = 0; i < nodes.size(); ++i) by_type[nodes[i].type].push_back(i);
  const double period = 360.0 / options.angle_bandwidth_deg;
  std::vector<Scored> all;
  std::set<std::vector<std::vector<std::size_t>>> seen;
  for (const auto& [type, members] : by_type) {
    if (members.size() < 2) continue;
    std::vector<Pair> pairs = neighbour_pairs(nodes, members, options.neighbours);
    add_predicted_pairs(nodes, members, diagonal, options, pairs);
    const Space spaces[3] = {Space{}, Space{{false, true, false, false}}, Space{{true, false, false, true}}};
    std::vector<std::vector<std::vector<std::size_t>>> full_space_chains;
    for (const Space& space : spaces) {
      std::vector<ShiftPoint> points;
      for (const Pair& p : pairs) {
        const ShiftPoint f = full_space_point(p.t, diagonal, options);  // alpha, log d, log s, beta
        if (!space.free[1] && !space.free[0]) points.push_back(f);
        else if (space.free[1]) points.push_back({f[0], f[2], f[3], 0});
        else points.push_back({f[1], f[2], 0, 0});
      }
      const int dims = !space.free[1] && !space.free[0] ? 4 : space.free[1] ? 3 : 2;
      const ShiftPoint periods = !space.free[1] && !space.free[0] ? ShiftPoint{period, 0, 0, period}
                                 : space.free[1]                ? ShiftPoint{period, 0, period, 0}
                                                                : ShiftPoint{0, 0, 0, 0};
      const ShiftClusters clusters = mean_shift(points, dims, periods);
      std::vector<std::vector<std::size_t>> members_of(clusters.centers.size());
      for (std::size_t p = 0; p < pairs.size(); ++p)
        if (clusters.labels[p] >= 0) members_of[static_cast<std::size_t>(clusters.labels[p])].push_back(p);
      for (const auto& cluster : members_of) {
        std::vector<std::vector<std::size_t>> chains = link_chains(pairs, cluster);
        if (dims == 4 && static_cast<int>(full_space_chains.size()) < options.max_branch_clusters) full_space_chains.push_back(chains);
        chains = split_linear(pairs, chains, space, options);
        Scored s;
        RuleCandidate& c = s.candidate;
        if (!fit_rule(pairs, chains, space, options, c.start, c.slope)) continue;
        c.child_type = type;
        std::vector<std::vector<std::size_t>> signature;
        for (const auto& chain : chains) {
          std::vector<std::size_t> group{pairs[chain.front()].from};
          for (std::size_t p : chain) {
            group.push_back(pairs[p].to);
            s.links.emplace_back(pairs[p].from, pairs[p].to);
          }
          c.absorbed += chain.size();
          c.counters.push_back(static_cast<int>(group.size()));
          signature.push_back(group);
          c.groups.push_back(std::move(group));
        }
        std::sort(signature.begin(), signature.end());
        if (!seen.insert(signature).second) continue;
        all.push_back(std::move(s));
      }
    }
    for (std::size_t a = 0; a < full_space_chains.size(); ++a)
      for (std::size_t b = a + 1; b < full_space_chains.size(); ++b)
        branching_candidates(pairs, full_space_chains[a], full_space_chains[b], type, all);
  }
  // Pairs of elements of different types (rule r1 with A != B and m = 1, folded to Q -> A T B):
  // each element with its nearest elements of other types, grouped by the two types.
  std::map<std::pair<std::string, std::string>, std::vector<Pair>> cross;
  {
    std::vector<std::pair<double, std::size_t>> distances;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      distances.clear();
      for (std::size_t j = 0; j < nodes.size(); ++j)
        if (nodes[j].type != nodes[i].type) distances.emplace_back((nodes[j].frame.position - nodes[i].exit.position).squaredNorm(), j);
      const std::size_t take = std::min<std::size_t>(static_cast<std::size_t>(std::max(options.neighbours, 1)), distances.size());
      std::partial_sort(distances.begin(), distances.begin() + static_cast<std::ptrdiff_t>(take), distances.end());
      for (std::size_t n = 0; n < take; ++n) {
        const std::size_t j = distances[n].second;
        cross[{nodes[i].type, nodes[j].type}].push_back(
            Pair{i, j, relative_transform(nodes[i].exit, nodes[j].frame), std::sqrt(distances[n].first)});
      }
    }
  }
  for (const auto& [types, pairs] : cross) {
    const auto& [first_type, second_type] = types;
    std::vector<ShiftPoint> points;
    for (const Pair& p : pairs) points.push_back(full_space_point(p.t, diagonal, options));
    const ShiftClusters clusters = mean_shift(points, 4, {period, 0, 0, period});
    std::vector<std::vector<std::size_t>> members_of(clusters.centers.size());
    for (std::size_t p = 0; p < pairs.size(); ++p)
      if (clusters.labels[p] >= 0) members_of[static_cast<std::size_t>(clusters.labels[p])].push_back(p);
    for (auto& cluster : members_of) {
      std::sort(cluster.begin(), cluster.end(), [&](std::size_t a, std::size_t b) {
        if (pairs[a].world_distance != pairs[b].world_distance) return pairs[a].world_distance < pairs[b].world_distance;
        return std::pair{pairs[a].from, pairs[a].to} < std::pair{pairs[b].from, pairs[b].to};
      });
      Scored s;
      RuleCandidate& c = s.candidate;
      c.pair = true;
      c.child_type = first_type;
      c.second_type = second_type;
      std::set<std::size_t> used;
      TurtleTransform sum{};
      const TurtleTransform reference = pairs[cluster.front()].t;
      for (std::size_t p : cluster) {
        if (used.count(pairs[p].from) || used.count(pairs[p].to)) continue;
        used.insert(pairs[p].from);
        used.insert(pairs[p].to);
        c.groups.push_back({pairs[p].from, pairs[p].to});
        c.counters.push_back(1);
        s.links.emplace_back(pairs[p].from, pairs[p].to);
        for (int k = 0; k < 4; ++k) sum[k] += is_angle(k) ? reference[k] + wrap_degrees(pairs[p].t[k] - reference[k]) : pairs[p].t[k];
      }
      c.absorbed = c.groups.size();
      for (int k = 0; k < 4; ++k) c.start[k] = is_angle(k) ? wrap_degrees(sum[k] / static_cast<double>(c.groups.size())) : sum[k] / static_cast<double>(c.groups.size());
      all.push_back(std::move(s));
    }
  }
  score(all, nodes, diagonal, options.weights);
  std::sort(all.begin(), all.end(), [](const Scored& x, const Scored& y) {
    const RuleCandidate &a = x.candidate, &b = y.candidate;
    if (std::abs(a.score - b.score) > 1e-6) return a.score > b.score;
    const int ca = transform_command_count(a.start, a.slope) + (a.branching ? transform_command_count(a.second, {}) + 2 : 0);
    const int cb = transform_command_count(b.start, b.slope) + (b.branching ? transform_command_count(b.second, {}) + 2 : 0);
    if (ca != cb) return ca < cb;  // the shorter rule first
    if (a.absorbed != b.absorbed) return a.absorbed > b.absorbed;
    if (a.branching != b.branching) return !a.branching;
    if (a.pair != b.pair) return !a.pair;
    if (a.child_type != b.child_type) return a.child_type < b.child_type;
    if (a.second_type != b.second_type) return a.second_type < b.second_type;
    if ((a.start[2] <= 1) != (b.start[2] <= 1)) return a.start[2] <= 1;  // things shrink as they grow
    if (a.start != b.start) return a.start < b.start;
    if (a.slope != b.slope) return a.slope < b.slope;
    return a.second < b.second;
  });
  std::vector<RuleCandidate> out;
  for (Scored& s : all) out.push_back(std::move(s.candidate));
  return out;
}

}  // namespace dg
