#pragma once
// A uniform grid over 2D segments for the collision and distance queries of guided growth.
// Each segment is listed in every cell its bounding box touches; segments outside the grid's
// box are clamped into the border cells, so no segment is ever lost (only queries far outside
// the box get slower).

#include "geometry/types.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace dg {

/// A stored segment with the id the growth gives it.
struct GridSegment {
  Vec2 a = Vec2::Zero();
  Vec2 b = Vec2::Zero();
  double id = 0;
};

/// A query result: which stored segment (index in insertion order), the query parameter where
/// it was met (along the query segment; for nearest(): the distance), and the closest point.
struct GridHit {
  std::size_t index = 0;
  double t = 0;
  Vec2 point = Vec2::Zero();
};

/// Uniform grid of segments; filled with insert(), emptied with reset(); removed segments keep
/// their index (it stays valid) but are no longer found.
class SegmentGrid {
 public:
  /// Empties the grid and lays `expected` segments out over the box [low, high] (drawing
  /// units): about two segments per cell, and cells not smaller than `min_cell`.
  void reset(const Vec2& low, const Vec2& high, std::size_t expected, double min_cell);

  /// Adds a segment; returns its index.
  std::size_t insert(const GridSegment& segment);

  /// Stops finding segment `index`.
  void remove(std::size_t index);

  /// Lays the cells out again for the segments still present (as reset() would for that many)
  /// without changing any index; for grids that grew far beyond what reset() expected.
  void relayout(double min_cell);

  /// Segments inserted so far (removed ones included): the bound of valid indices.
  std::size_t size() const { return segments_.size(); }
  /// Segments present (not removed).
  std::size_t live() const { return live_; }
  const GridSegment& operator[](std::size_t index) const { return segments_[index]; }

  /// The stored segment that the query segment [p, q] meets first, with t in (min_t, 1]
  /// along [p, q]; nothing when no stored segment is met. Parallel overlaps are not hits.
  std::optional<GridHit> first_hit(const Vec2& p, const Vec2& q, double min_t, std::optional<double> only_id = {}) const;

  /// The stored segment closest to p (t = its distance), or nothing when the grid is empty.
  /// Both queries consider only segments with id `only_id` when it is given.
  std::optional<GridHit> nearest(const Vec2& p, std::optional<double> only_id = {}) const;

 private:
  std::size_t cell_of(int x, int y) const { return static_cast<std::size_t>(y) * nx_ + x; }
  int column(double x) const;
  int row(double y) const;
  bool seen(std::size_t index) const;

  Vec2 low_ = Vec2::Zero();
  double cell_ = 1;
  int nx_ = 1, ny_ = 1;
  void add_to_cells(std::size_t index);

  Vec2 high_ = Vec2::Zero();
  std::size_t live_ = 0;
  std::vector<GridSegment> segments_;
  std::vector<char> alive_;
  std::vector<std::vector<std::uint32_t>> cells_;
  mutable std::vector<std::uint32_t> stamps_;  // per segment: the query that last looked at it
  mutable std::uint32_t query_ = 0;
};

}  // namespace dg
