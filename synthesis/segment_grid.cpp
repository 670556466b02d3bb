#include "synthesis/segment_grid.h"

#include "synthesis/segment2d.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dg {

void SegmentGrid::reset(const Vec2& low, const Vec2& high, std::size_t expected, double min_cell) {
  const Vec2 size = (high - low).cwiseMax(Vec2::Constant(1e-9));
  const double area = size.x() * size.y();
  double cell = std::sqrt(2 * area / static_cast<double>(std::max<std::size_t>(expected, 1)));
  cell = std::max({cell, min_cell, size.maxCoeff() / 2048});
  const int nx = std::max(1, static_cast<int>(std::ceil(size.x() / cell)));
  const int ny = std::max(1, static_cast<int>(std::ceil(size.y() / cell)));
  low_ = low;
  high_ = high;
  cell_ = cell;
  if (nx != nx_ || ny != ny_ || cells_.empty()) {
    nx_ = nx;
    ny_ = ny;
    cells_.assign(static_cast<std::size_t>(nx) * ny, {});
  } else {
    for (auto& list : cells_) list.clear();
  }
  segments_.clear();
  stamps_.clear();
  alive_.clear();
  live_ = 0;
}

void SegmentGrid::relayout(double min_cell) {
  std::vector<GridSegment> segments = std::move(segments_);
  std::vector<char> alive = std::move(alive_);
  reset(low_, high_, live_, min_cell);
  segments_ = std::move(segments);
  alive_ = std::move(alive);
  stamps_.assign(segments_.size(), 0);
  for (std::size_t i = 0; i < segments_.size(); ++i)
    if (alive_[i]) {
      ++live_;
      add_to_cells(i);
    }
}

void SegmentGrid::remove(std::size_t index) {
  if (alive_[index]) {
    alive_[index] = 0;
    --live_;
  }
}

int SegmentGrid::column(double x) const {
  const double c = std::floor((x - low_.x()) / cell_);
  return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(nx_ - 1)));
}

int SegmentGrid::row(double y) const {
  const double r = std::floor((y - low_.y()) / cell_);
  return static_cast<int>(std::clamp(r, 0.0, static_cast<double>(ny_ - 1)));
}

std::size_t SegmentGrid::insert(const GridSegment& segment) {
  const std::size_t index = segments_.size();
  segments_.push_back(segment);
  stamps_.push_back(0);
  alive_.push_back(1);
  ++live_;
  add_to_cells(index);
  return index;
}

void SegmentGrid::add_to_cells(std::size_t index) {
  const GridSegment& segment = segments_[index];
  const double pad = cell_ * 1e-9;
  const Vec2 lo = segment.a.cwiseMin(segment.b) - Vec2::Constant(pad);
  const Vec2 hi = segment.a.cwiseMax(segment.b) + Vec2::Constant(pad);
  for (int y = row(lo.y()); y <= row(hi.y()); ++y)
    for (int x = column(lo.x()); x <= column(hi.x()); ++x) cells_[cell_of(x, y)].push_back(static_cast<std::uint32_t>(index));
}

bool SegmentGrid::seen(std::size_t index) const {
  if (stamps_[index] == query_ || !alive_[index]) return true;
  stamps_[index] = query_;
  return false;
}

std::optional<GridHit> SegmentGrid::first_hit(const Vec2& p, const Vec2& q, double min_t,
                                              std::optional<double> only_id) const {
  if (live_ == 0) return std::nullopt;
  ++query_;
  std::optional<GridHit> best;
  auto test_cell = [&](int x, int y) {
    for (std::uint32_t index : cells_[cell_of(x, y)]) {
      if (seen(index) || (only_id && segments_[index].id != *only_id)) continue;
      const GridSegment& s = segments_[index];
      const auto crossing = cross_segments(p, q, s.a, s.b);
      if (crossing && crossing->s > min_t && (!best || crossing->s < best->t))
        best = GridHit{index, crossing->s, p + crossing->s * (q - p)};
    }
  };
  const Vec2 high = low_ + cell_ * Vec2(nx_, ny_);
  auto inside = [&](const Vec2& v) { return (v.array() >= low_.array()).all() && (v.array() < high.array()).all(); };
  if (!inside(p) || !inside(q)) {  // rare: test every cell of the bounding box (clamped)
    for (int y = row(std::min(p.y(), q.y())); y <= row(std::max(p.y(), q.y())); ++y)
      for (int x = column(std::min(p.x(), q.x())); x <= column(std::max(p.x(), q.x())); ++x) test_cell(x, y);
    return best;
  }
  // Walk the cells along [p, q] in order (Amanatides & Woo), stopping once the best hit lies
  // before the exit of the current cell.
  int x = column(p.x()), y = row(p.y());
  const int end_x = column(q.x()), end_y = row(q.y());
  const Vec2 d = q - p;
  const int step_x = d.x() > 0 ? 1 : -1, step_y = d.y() > 0 ? 1 : -1;
  const double inf = std::numeric_limits<double>::infinity();
  auto boundary_t = [&](double origin, double delta, int index, int step, double low) {
    if (delta == 0) return inf;
    const double edge = low + (index + (step > 0 ? 1 : 0)) * cell_;
    return (edge - origin) / delta;
  };
  double t_x = boundary_t(p.x(), d.x(), x, step_x, low_.x());
  double t_y = boundary_t(p.y(), d.y(), y, step_y, low_.y());
  const double delta_x = d.x() == 0 ? inf : cell_ / std::abs(d.x());
  const double delta_y = d.y() == 0 ? inf : cell_ / std::abs(d.y());
  for (int guard = 0; guard < nx_ + ny_ + 2; ++guard) {
    test_cell(x, y);
    const double t_exit = std::min(t_x, t_y);
    if (best && best->t <= t_exit) break;
    if (x == end_x && y == end_y) break;
    if (t_x < t_y) {
      if (x + step_x < 0 || x + step_x >= nx_) break;
      x += step_x;
      t_x += delta_x;
    } else {
      if (y + step_y < 0 || y + step_y >= ny_) break;
      y += step_y;
      t_y += delta_y;
    }
  }
  return best;
}

std::optional<GridHit> SegmentGrid::nearest(const Vec2& p, std::optional<double> only_id) const {
  if (live_ == 0) return std::nullopt;
  ++query_;
  std::optional<GridHit> best;
  const int cx = column(p.x()), cy = row(p.y());
  // Distance from p to the outside of its own cell ring r: at least r cells minus p's offset.
  const double offset = std::max({std::abs(p.x() - (low_.x() + (cx + 0.5) * cell_)),
                                  std::abs(p.y() - (low_.y() + (cy + 0.5) * cell_))});
  const int max_ring = std::max(nx_, ny_);
  for (int ring = 0; ring <= max_ring; ++ring) {
    for (int y = cy - ring; y <= cy + ring; ++y) {
      if (y < 0 || y >= ny_) continue;
      const bool edge_row = y == cy - ring || y == cy + ring;
      for (int x = cx - ring; x <= cx + ring; x += edge_row ? 1 : 2 * ring) {
        if (x >= 0 && x < nx_)
          for (std::uint32_t index : cells_[cell_of(x, y)]) {
            if (seen(index) || (only_id && segments_[index].id != *only_id)) continue;
            const GridSegment& s = segments_[index];
            const double u = closest_parameter(p, s.a, s.b);
            const Vec2 point = s.a + u * (s.b - s.a);
            const double distance = (point - p).norm();
            if (!best || distance < best->t) best = GridHit{index, distance, point};
          }
        if (ring == 0) break;
      }
    }
    if (best && best->t <= (ring + 0.5) * cell_ - offset) break;
  }
  return best;
}

}  // namespace dg
