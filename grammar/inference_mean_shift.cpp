#include "grammar/inference_mean_shift.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

namespace dg {

namespace {

using Cell = std::array<std::int64_t, 4>;

struct Grid {
  int dimensions = 1;
  ShiftPoint periods{};
  std::array<std::int64_t, 4> cell_counts{};  // periodic: cells per period (each at least 1 unit wide)
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells;

  std::int64_t wrap_cell(int k, std::int64_t c) const {
    if (periods[k] <= 0) return c;
    const std::int64_t n = cell_counts[k];
    return ((c % n) + n) % n;
  }
  Cell cell_of(const ShiftPoint& p) const {
    Cell c{0, 0, 0, 0};
    for (int k = 0; k < dimensions; ++k) {
      const double x = periods[k] > 0 ? p[k] * static_cast<double>(cell_counts[k]) / periods[k] : p[k];
      c[k] = wrap_cell(k, static_cast<std::int64_t>(std::floor(x)));
    }
    return c;
  }
  static std::uint64_t key(const Cell& c) {
    std::uint64_t h = 0;
    for (std::int64_t v : c) h = h * 1000003u + static_cast<std::uint64_t>(v + (std::int64_t{1} << 40));
    return h;
  }
};

// a - b for coordinates in [0, period): the shorter way round.
double wrapped_difference(double a, double b, double period) {
  double d = a - b;
  if (period > 0) {
    if (d > period / 2) d -= period;
    else if (d <= -period / 2) d += period;
  }
  return d;
}

double normalize(double x, double period) {
  if (period <= 0) return x;
  double r = std::fmod(x, period);
  if (r < 0) r += period;
  return r;
}

}  // namespace

ShiftClusters mean_shift(const std::vector<ShiftPoint>& input, int dimensions, const ShiftPoint& periods) {
  ShiftClusters result;
  result.labels.assign(input.size(), -1);
  if (input.empty()) return result;
  Grid grid;
  grid.dimensions = dimensions;
  grid.periods = periods;
  for (int k = 0; k < dimensions; ++k)
    grid.cell_counts[k] = periods[k] > 0 ? std::max<std::int64_t>(1, static_cast<std::int64_t>(std::floor(periods[k]))) : 0;
  std::vector<ShiftPoint> points(input);
  for (ShiftPoint& p : points)
    for (int k = 0; k < dimensions; ++k) p[k] = normalize(p[k], periods[k]);
  std::unordered_map<std::uint64_t, Cell> cell_ids;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Cell c = grid.cell_of(points[i]);
    grid.cells[Grid::key(c)].push_back(i);
    cell_ids.emplace(Grid::key(c), c);
  }
  auto distance = [&](const ShiftPoint& a, const ShiftPoint& b) {
    double s = 0;
    for (int k = 0; k < dimensions; ++k) {
      const double d = wrapped_difference(a[k], b[k], periods[k]);
      s += d * d;
    }
    return std::sqrt(s);
  };
  // Calls visit(i) for every point in the cells around x.
  auto for_neighbours = [&](const ShiftPoint& x, auto&& visit) {
    const Cell c = grid.cell_of(x);
    const int total = static_cast<int>(std::pow(3, dimensions));
    for (int code = 0; code < total; ++code) {
      Cell n = c;
      int rest = code;
      bool duplicate = false;
      for (int k = 0; k < dimensions; ++k) {
        n[k] = grid.wrap_cell(k, c[k] + rest % 3 - 1);
        if (periods[k] > 0 && grid.cell_counts[k] < 3 && rest % 3 != 1 && n[k] == c[k]) duplicate = true;
        rest /= 3;
      }
      if (duplicate) continue;
      const auto it = grid.cells.find(Grid::key(n));
      if (it == grid.cells.end()) continue;
      for (std::size_t i : it->second) visit(i);
    }
  };
  // Shift each seed (the mean of an occupied cell) to its mode.
  std::vector<ShiftPoint> modes;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> accepted;  // cell -> modes in or next to it
  std::vector<std::uint64_t> keys;
  for (const auto& entry : grid.cells) keys.push_back(entry.first);
  std::sort(keys.begin(), keys.end());
  for (std::uint64_t key : keys) {
    const std::vector<std::size_t>& members = grid.cells[key];
    ShiftPoint x = points[members.front()];
    for (int iteration = 0; iteration < 50; ++iteration) {
      ShiftPoint sum{0, 0, 0, 0};
      std::size_t count = 0;
      for_neighbours(x, [&](std::size_t i) {
        if (distance(points[i], x) > 1) return;
        for (int k = 0; k < dimensions; ++k) sum[k] += wrapped_difference(points[i][k], x[k], periods[k]);
        ++count;
      });
      if (count == 0) break;
      double shift = 0;
      for (int k = 0; k < dimensions; ++k) {
        const double step = sum[k] / static_cast<double>(count);
        x[k] = normalize(x[k] + step, periods[k]);
        shift += step * step;
      }
      if (shift < 1e-8) break;
    }
    bool merged = false;
    const auto near = accepted.find(Grid::key(grid.cell_of(x)));
    for (std::size_t m : near == accepted.end() ? std::vector<std::size_t>{} : near->second)
      if (distance(modes[m], x) < 0.5) merged = true;
    if (!merged) {
      // Registered in its cell and the neighbouring cells, so one lookup finds every mode within 0.5.
      const Cell c = grid.cell_of(x);
      const int total = static_cast<int>(std::pow(3, dimensions));
      for (int code = 0; code < total; ++code) {
        Cell n = c;
        int rest = code;
        for (int k = 0; k < dimensions; ++k, rest /= 3) n[k] = grid.wrap_cell(k, c[k] + rest % 3 - 1);
        auto& list = accepted[Grid::key(n)];
        if (list.empty() || list.back() != modes.size()) list.push_back(modes.size());
      }
      modes.push_back(x);
    }
  }
  // Assign points to the nearest mode within radius 1 (modes looked up in the same cells).
  Grid mode_grid = grid;
  mode_grid.cells.clear();
  for (std::size_t m = 0; m < modes.size(); ++m) mode_grid.cells[Grid::key(mode_grid.cell_of(modes[m]))].push_back(m);
  std::swap(grid.cells, mode_grid.cells);  // for_neighbours now visits modes
  std::vector<std::size_t> sizes(modes.size(), 0);
  std::vector<int> labels(points.size(), -1);
  for (std::size_t i = 0; i < points.size(); ++i) {
    double best = 1;
    std::size_t chosen = modes.size();
    for_neighbours(points[i], [&](std::size_t m) {
      const double d = distance(points[i], modes[m]);
      if (d < best || (d == best && m < chosen)) best = d, chosen = m;
    });
    if (chosen < modes.size()) labels[i] = static_cast<int>(chosen), ++sizes[chosen];
  }
  std::vector<std::size_t> order(modes.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (sizes[a] != sizes[b]) return sizes[a] > sizes[b];
    return modes[a] < modes[b];
  });
  std::vector<int> rank(modes.size(), -1);
  for (std::size_t r = 0; r < order.size(); ++r) {
    if (sizes[order[r]] == 0) continue;
    rank[order[r]] = static_cast<int>(result.centers.size());
    result.centers.push_back(modes[order[r]]);
    result.sizes.push_back(sizes[order[r]]);
  }
  for (std::size_t i = 0; i < points.size(); ++i)
    result.labels[i] = labels[i] >= 0 ? rank[static_cast<std::size_t>(labels[i])] : -1;
  return result;
}

}  // namespace dg
