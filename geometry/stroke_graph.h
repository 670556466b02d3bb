#pragma once
// The stroke graph of a skeleton: nodes where strokes end or meet, chains of pixel centres
// between them, and the straight pieces of each chain (split at corners).

#include "geometry/skeleton.h"
#include "geometry/types.h"

#include <cstddef>
#include <vector>

namespace dg {

/// One chain of skeleton pixels from node `from` to node `to` (equal for a closed loop).
struct StrokeChain {
  std::size_t from = 0;
  std::size_t to = 0;
  std::vector<Vec2> points;  ///< pixel centres (x + 0.5, y + 0.5), y down; first and last are the node positions
};

/// Nodes (ends: one neighbour; junctions: three or more branches, adjacent junction pixels
/// merged into one node at their mean position) and the chains between them. A closed loop
/// without nodes gets one node at its first pixel.
struct StrokeGraph {
  std::vector<Vec2> nodes;  ///< pixel units, y down
  std::vector<StrokeChain> chains;
};

/// Traces the 8-connected skeleton (one pixel wide, e.g. from thin()).
StrokeGraph trace_strokes(const BinaryImage& skeleton);

/// Indices of the corners of `points` by Douglas–Peucker: the chain is split at its farthest
/// point from the chord while that is farther than `tolerance`; first and last are corners.
std::vector<std::size_t> chain_corners(const std::vector<Vec2>& points, double tolerance);

/// Corner points of a chain: chain_corners(points, tolerance), then every inner piece shorter
/// than `min_piece` (a corner the skeleton rounded off) is replaced by the intersection of its
/// neighbours' lines when that lies within 2 min_piece of it. A `closed` chain (first point equal
/// to the last) is treated cyclically, and its vertices turning by less than 12 degrees are
/// dropped (the loop's arbitrary start). Pixel units.
std::vector<Vec2> fit_polyline(const std::vector<Vec2>& points, bool closed, double tolerance, double min_piece);

/// Connected groups of chains (sharing nodes), each a list of chain indices in input order.
std::vector<std::vector<std::size_t>> stroke_components(const StrokeGraph& graph);

}  // namespace dg
