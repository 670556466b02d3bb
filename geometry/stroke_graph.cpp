#include "geometry/stroke_graph.h"

#include <array>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace dg {

namespace {

// Neighbour offsets: the four 4-neighbours first, so walks prefer them over diagonals.
constexpr std::array<std::array<int, 2>, 8> kOffsets{{{0, -1}, {1, 0}, {0, 1}, {-1, 0}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}}};
constexpr std::array<std::array<int, 2>, 8> kRing{{{0, -1}, {1, -1}, {1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}}};

Vec2 centre(int x, int y) { return Vec2(x + 0.5, y + 0.5); }

// Number of separate branches around a pixel: 0 -> 1 transitions around its 8-ring, counting a
// diagonal neighbour only when neither adjacent 4-neighbour is on (so staircases count once).
int branches(const BinaryImage& s, int x, int y) {
  std::array<int, 8> on{};
  for (int k = 0; k < 8; ++k) on[k] = s.at(x + kRing[k][0], y + kRing[k][1]);
  for (int k = 1; k < 8; k += 2)
    if (on[k] && (on[k - 1] || on[(k + 1) % 8])) on[k] = 0;
  int count = 0, total = 0;
  for (int k = 0; k < 8; ++k) {
    total += on[k];
    count += on[k] && !on[(k + 7) % 8];
  }
  return total == 8 ? 0 : count;
}

void split(const std::vector<Vec2>& points, std::size_t a, std::size_t b, double tolerance, std::vector<std::size_t>& corners) {
  if (b <= a + 1) return;
  const Vec2 chord = points[b] - points[a];
  const double length = chord.norm();
  double worst = -1;
  std::size_t at = a;
  for (std::size_t k = a + 1; k < b; ++k) {
    const Vec2 d = points[k] - points[a];
    const double distance = length > 0 ? std::abs(d.x() * chord.y() - d.y() * chord.x()) / length : d.norm();
    if (distance > worst) worst = distance, at = k;
  }
  if (worst <= tolerance) return;
  split(points, a, at, tolerance, corners);
  corners.push_back(at);
  split(points, at, b, tolerance, corners);
}

}  // namespace

StrokeGraph trace_strokes(const BinaryImage& skeleton) {
  StrokeGraph graph;
  const int w = skeleton.width, h = skeleton.height;
  auto index = [w](int x, int y) { return static_cast<std::size_t>(y) * w + x; };
  constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::vector<std::size_t> node_of(skeleton.ink.size(), none);
  // Node pixels: ends (one branch) and junctions (three or more), grouped by 8-adjacency.
  std::vector<std::uint8_t> is_node(skeleton.ink.size(), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (skeleton.at(x, y)) {
        const int b = branches(skeleton, x, y);
        is_node[index(x, y)] = b == 1 || b >= 3 || b == 0;
      }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!is_node[index(x, y)] || node_of[index(x, y)] != none) continue;
      const std::size_t id = graph.nodes.size();
      std::vector<std::array<int, 2>> queue{{x, y}};
      node_of[index(x, y)] = id;
      Vec2 sum = Vec2::Zero();
      for (std::size_t q = 0; q < queue.size(); ++q) {
        const auto [cx, cy] = queue[q];
        sum += centre(cx, cy);
        for (const auto& o : kOffsets) {
          const int nx = cx + o[0], ny = cy + o[1];
          if (!skeleton.at(nx, ny) || !is_node[index(nx, ny)] || node_of[index(nx, ny)] != none) continue;
          node_of[index(nx, ny)] = id;
          queue.push_back({nx, ny});
        }
      }
      graph.nodes.push_back(sum / static_cast<double>(queue.size()));
    }
  std::vector<std::uint8_t> visited(skeleton.ink.size(), 0);
  // Walks from pixel (x, y) (already the chain's second pixel) until a node pixel is reached.
  auto walk = [&](std::size_t start_node, int x, int y, std::vector<Vec2>& points) -> std::size_t {
    int px = -1, py = -1;
    for (;;) {
      visited[index(x, y)] = 1;
      points.push_back(centre(x, y));
      int next_x = -1, next_y = -1;
      for (const auto& o : kOffsets) {
        const int nx = x + o[0], ny = y + o[1];
        if (!skeleton.at(nx, ny) || (nx == px && ny == py)) continue;
        const std::size_t node = node_of[index(nx, ny)];
        if (node != none && (node != start_node || points.size() >= 3)) return node;
        if (node == none && !visited[index(nx, ny)] && next_x < 0) next_x = nx, next_y = ny;
      }
      if (next_x < 0) return none;
      px = x, py = y, x = next_x, y = next_y;
    }
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t node = node_of[index(x, y)];
      if (node == none) continue;
      for (const auto& o : kOffsets) {
        const int nx = x + o[0], ny = y + o[1];
        if (!skeleton.at(nx, ny)) continue;
        const std::size_t other = node_of[index(nx, ny)];
        if (other != none) continue;  // pixels of the same or an adjacent node
        if (visited[index(nx, ny)]) continue;
        StrokeChain chain;
        chain.from = node;
        chain.points.push_back(graph.nodes[node]);
        const std::size_t end = walk(node, nx, ny, chain.points);
        chain.to = end == none ? node : end;
        chain.points.push_back(graph.nodes[chain.to]);
        graph.chains.push_back(std::move(chain));
      }
    }
  // Loops without any node.
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!skeleton.at(x, y) || visited[index(x, y)] || node_of[index(x, y)] != none) continue;
      const std::size_t id = graph.nodes.size();
      graph.nodes.push_back(centre(x, y));
      node_of[index(x, y)] = id;
      visited[index(x, y)] = 1;
      StrokeChain chain;
      chain.from = chain.to = id;
      chain.points.push_back(centre(x, y));
      for (const auto& o : kOffsets) {
        const int nx = x + o[0], ny = y + o[1];
        if (!skeleton.at(nx, ny) || visited[index(nx, ny)]) continue;
        walk(id, nx, ny, chain.points);
        break;
      }
      chain.points.push_back(centre(x, y));
      graph.chains.push_back(std::move(chain));
    }
  return graph;
}

std::vector<std::size_t> chain_corners(const std::vector<Vec2>& points, double tolerance) {
  std::vector<std::size_t> corners{0};
  if (points.size() < 2) return corners;
  const std::size_t last = points.size() - 1;
  if ((points[last] - points[0]).norm() < 1e-9 && points.size() > 3) {
    // A closed loop: split first at the point farthest from the start.
    std::size_t far = 0;
    for (std::size_t k = 0; k < points.size(); ++k)
      if ((points[k] - points[0]).norm() > (points[far] - points[0]).norm()) far = k;
    split(points, 0, far, tolerance, corners);
    corners.push_back(far);
    split(points, far, last, tolerance, corners);
  } else {
    split(points, 0, last, tolerance, corners);
  }
  corners.push_back(last);
  return corners;
}

std::vector<Vec2> fit_polyline(const std::vector<Vec2>& points, bool closed, double tolerance, double min_piece) {
  std::vector<Vec2> v;
  for (std::size_t k : chain_corners(points, tolerance)) v.push_back(points[k]);
  if (closed && v.size() > 3) v.pop_back();
  else closed = false;
  const std::size_t n0 = v.size();
  auto at = [&](std::ptrdiff_t k) -> Vec2& {
    const auto n = static_cast<std::ptrdiff_t>(v.size());
    return v[static_cast<std::size_t>(((k % n) + n) % n)];
  };
  for (std::size_t round = 0; round < n0; ++round) {
    const auto n = static_cast<std::ptrdiff_t>(v.size());
    if (n < (closed ? 4 : 4)) break;
    // The shortest inner piece below min_piece (open chains keep their end pieces).
    std::ptrdiff_t best = -1;
    double best_length = min_piece;
    for (std::ptrdiff_t i = closed ? 0 : 1; i < (closed ? n : n - 2); ++i) {
      const double length = (at(i + 1) - at(i)).norm();
      if (length < best_length) best_length = length, best = i;
    }
    if (best < 0) break;
    const Vec2 a0 = at(best - 1), a1 = at(best), b0 = at(best + 1), b1 = at(best + 2);
    const Vec2 da = a1 - a0, db = b1 - b0;
    const double cross = da.x() * db.y() - da.y() * db.x();
    const Vec2 middle = (a1 + b0) / 2;
    Vec2 corner = middle;
    if (std::abs(cross) > 1e-9 * da.norm() * db.norm()) {
      const double t = ((b0 - a0).x() * db.y() - (b0 - a0).y() * db.x()) / cross;
      corner = a0 + t * da;
    }
    if ((corner - middle).norm() > 2 * min_piece) corner = middle;
    at(best) = corner;
    v.erase(v.begin() + ((best + 1) % n));
  }
  if (closed) {
    std::vector<Vec2> kept;
    const std::size_t n = v.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Vec2 in = v[k] - v[(k + n - 1) % n], out = v[(k + 1) % n] - v[k];
      const double turn = std::abs(std::atan2(in.x() * out.y() - in.y() * out.x(), in.dot(out))) * 180 / 3.14159265358979;
      if (turn >= 12 || n <= 3) kept.push_back(v[k]);
    }
    v = kept;
    if (!v.empty()) v.push_back(v.front());
  }
  return v;
}

std::vector<std::vector<std::size_t>> stroke_components(const StrokeGraph& graph) {
  std::vector<std::size_t> parent(graph.nodes.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](std::size_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const StrokeChain& chain : graph.chains) parent[find(chain.from)] = find(chain.to);
  std::unordered_map<std::size_t, std::size_t> component_of_root;
  std::vector<std::vector<std::size_t>> components;
  for (std::size_t c = 0; c < graph.chains.size(); ++c) {
    const std::size_t root = find(graph.chains[c].from);
    const auto [it, added] = component_of_root.emplace(root, components.size());
    if (added) components.emplace_back();
    components[it->second].push_back(c);
  }
  return components;
}

}  // namespace dg
