#include "grammar/instance_tree.h"

#include <cmath>
#include <queue>
#include <tuple>
#include <unordered_map>

namespace dg {

namespace {

// Merges end points closer than `tolerance` into one vertex id (hash grid of that cell size).
class VertexIndex {
 public:
  explicit VertexIndex(double tolerance) : tolerance_(tolerance > 0 ? tolerance : 1e-9) {}

  std::size_t id(const Vec2& p) {
    const long long cx = cell(p.x()), cy = cell(p.y());
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        const auto it = grid_.find(key(cx + dx, cy + dy));
        if (it == grid_.end()) continue;
        for (std::size_t v : it->second)
          if ((points_[v] - p).norm() <= tolerance_) return v;
      }
    points_.push_back(p);
    grid_[key(cx, cy)].push_back(points_.size() - 1);
    return points_.size() - 1;
  }

 private:
  long long cell(double x) const { return static_cast<long long>(std::floor(x / tolerance_)); }
  static long long key(long long x, long long y) { return x * 73856093LL ^ y * 19349663LL; }
  double tolerance_;
  std::vector<Vec2> points_;
  std::unordered_map<long long, std::vector<std::size_t>> grid_;
};

Vec2 direction(const TreeSegment& s) {
  const Vec2 d = s.end - s.start;
  const double n = d.norm();
  return n > 0 ? Vec2(d / n) : Vec2(1, 0);
}

}  // namespace

double normalized_pair_distance(const TreeSegment& x, const TreeSegment& y) {
  const Vec2 cx = (x.start + x.end) / 2, cy = (y.start + y.end) / 2;
  const double hx = (x.end - x.start).norm(), hy = (y.end - y.start).norm();
  const double sum = hx + hy;
  if (sum <= 0) return 0;
  const Vec2 between = cy - cx;
  const double along_x = std::abs(between.dot(direction(x))), along_y = std::abs(between.dot(direction(y)));
  return (along_x + along_y - sum) / (0.5 * sum);
}

InstanceTree build_instance_tree(const std::vector<TreeSegment>& segments, std::size_t root, bool reverse_root,
                                 const InstanceTreeOptions& options) {
  InstanceTree tree;
  if (root >= segments.size()) return tree;
  VertexIndex vertices(options.join_tolerance);
  std::vector<std::size_t> start_id(segments.size()), end_id(segments.size());
  std::unordered_map<std::size_t, std::vector<std::pair<std::size_t, bool>>> incident;  // vertex -> (segment, reversed)
  for (std::size_t i = 0; i < segments.size(); ++i) {
    start_id[i] = vertices.id(segments[i].start);
    end_id[i] = vertices.id(segments[i].end);
    incident[start_id[i]].emplace_back(i, false);
    if (!options.directed) incident[end_id[i]].emplace_back(i, true);
  }
  std::vector<bool> used(segments.size(), false);
  std::vector<std::size_t> end_vertex;  // per node
  // Candidate links (D_s, parent node, segment, reversed), smallest first.
  using Link = std::tuple<double, std::size_t, std::size_t, bool>;
  std::priority_queue<Link, std::vector<Link>, std::greater<>> links;
  auto add_node = [&](std::size_t segment, bool reversed, std::size_t parent, bool has_parent) {
    TreeSegment s = segments[segment];
    if (reversed) std::swap(s.start, s.end);
    used[segment] = true;
    const std::size_t node = tree.nodes.size();
    tree.nodes.push_back(s);
    tree.source.push_back(segment);
    tree.children.emplace_back();
    end_vertex.push_back(reversed ? start_id[segment] : end_id[segment]);
    if (has_parent) tree.children[parent].push_back(node);
    const auto it = incident.find(end_vertex[node]);
    if (it == incident.end()) return;
    for (const auto& [next, next_reversed] : it->second) {
      if (used[next]) continue;
      TreeSegment candidate = segments[next];
      if (next_reversed) std::swap(candidate.start, candidate.end);
      const double distance = normalized_pair_distance(s, candidate);
      if (distance <= options.max_distance) links.emplace(distance, node, next, next_reversed);
    }
  };
  add_node(root, reverse_root, 0, false);
  while (!links.empty()) {
    const auto [distance, parent, segment, reversed] = links.top();
    links.pop();
    if (used[segment]) continue;
    add_node(segment, reversed, parent, true);
  }
  for (bool u : used)
    if (!u) ++tree.unreached;
  return tree;
}

InstanceTree build_ordered_instance_tree(const std::vector<TreeSegment>& segments, double join_tolerance) {
  InstanceTree tree;
  VertexIndex vertices(join_tolerance);
  std::unordered_map<std::size_t, std::size_t> latest_end;  // vertex -> latest node ending there
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const std::size_t start = vertices.id(segments[i].start), end = vertices.id(segments[i].end);
    const auto parent = latest_end.find(start);
    if (i > 0 && parent == latest_end.end()) {
      ++tree.unreached;
      continue;
    }
    const std::size_t node = tree.nodes.size();
    tree.nodes.push_back(segments[i]);
    tree.source.push_back(i);
    tree.children.emplace_back();
    if (i > 0) tree.children[parent->second].push_back(node);
    latest_end[end] = node;
  }
  return tree;
}

}  // namespace dg
