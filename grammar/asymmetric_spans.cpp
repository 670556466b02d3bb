#include "grammar/asymmetric_spans.h"

#include <algorithm>
#include <cstdint>
#include <queue>
#include <utility>

namespace dg {

std::vector<PositionSpan> asymmetric_spans(const VoxelSurface& surface, const std::vector<char>& symmetric, const Vec3& d,
                                           double r) {
  const std::size_t n = surface.cell_count();
  std::vector<PositionSpan> spans(n);
  // One bounded Dijkstra per asymmetric cell bordering the symmetric area; `visit` stamps the
  // cells reached by the current search so the distances need no reset.
  std::vector<double> distance(n, 0.0);
  std::vector<std::uint32_t> visit(n, 0);
  std::uint32_t stamp = 0;
  std::vector<std::uint32_t> reached;
  using Entry = std::pair<double, std::uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  for (std::uint32_t source = 0; source < n; ++source) {
    if (symmetric[source]) continue;
    const auto neighbours = surface.neighbours(source);
    if (std::none_of(neighbours.begin(), neighbours.end(), [&](std::uint32_t c) { return symmetric[c] != 0; })) continue;
    const double s = d.dot(surface.centre(source));
    ++stamp;
    reached.clear();
    visit[source] = stamp;
    distance[source] = 0.0;
    queue.emplace(0.0, source);
    while (!queue.empty()) {
      const auto [dist, c] = queue.top();
      queue.pop();
      if (dist > distance[c]) continue;
      const Vec3 centre = surface.centre(c);
      for (std::uint32_t m : surface.neighbours(c)) {
        if (!symmetric[m]) continue;
        const double candidate = dist + (surface.centre(m) - centre).norm();
        if (candidate > r || (visit[m] == stamp && candidate >= distance[m])) continue;
        if (visit[m] != stamp) reached.push_back(m);
        visit[m] = stamp;
        distance[m] = candidate;
        queue.emplace(candidate, m);
      }
    }
    for (std::uint32_t c : reached) {
      spans[c].lo = std::min(spans[c].lo, s);
      spans[c].hi = std::max(spans[c].hi, s);
    }
  }
  return spans;
}

}  // namespace dg
