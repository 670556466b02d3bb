#pragma once
// Guo et al. 2020 §4.2: the n-ary instance tree. Straight segments (atomic instances of `F`)
// are linked where one starts at the end of another; each candidate link is weighted by the
// normalized pairwise distance D_s (Eq. 4), links above the threshold (1.2) are dropped, and a
// minimum spanning tree is grown from the root segment. Every node is then oriented away from
// the root, which is how the turtle walks it.

#include "geometry/types.h"

#include <cstddef>
#include <vector>

namespace dg {

/// A straight segment in y-up drawing units, walked from start to end.
struct TreeSegment {
  Vec2 start = Vec2::Zero();
  Vec2 end = Vec2::Zero();
};

/// The spanning tree: nodes in the order Prim's algorithm added them (root first).
struct InstanceTree {
  std::vector<TreeSegment> nodes;                 ///< oriented away from the root
  std::vector<std::size_t> source;                ///< index of each node's input segment
  std::vector<std::vector<std::size_t>> children;  ///< node indices, in the order they were linked
  std::size_t unreached = 0;                      ///< input segments not connected to the root
};

/// Guo's Eq. 4: (|proj of c_y - c_x on heading x| + |proj on heading y| - (h_x + h_y)) /
/// (0.5 (h_x + h_y)), with c the centres, h the lengths. 0 for collinear neighbours, negative for
/// a branch leaving at an angle; larger the farther apart.
double normalized_pair_distance(const TreeSegment& x, const TreeSegment& y);

/// Options of the tree construction.
struct InstanceTreeOptions {
  double join_tolerance = 1e-3;  ///< end points closer than this (drawing units) are one point
  double max_distance = 1.2;     ///< links with D_s above this are dropped (Guo: 1.2)
  bool directed = true;          ///< segments keep their direction (vector input); otherwise
                                 ///< each is oriented away from the root (pixel input)
};

/// The instance tree grown from segments[root] (reversed first when `reverse_root`): a segment
/// may hang below a node when it starts (or, undirected, has an end) where the node ends; among
/// all such links Prim's algorithm keeps the ones of least D_s. Ties go to lower indices, so the
/// result depends only on the input order through them.
InstanceTree build_instance_tree(const std::vector<TreeSegment>& segments, std::size_t root, bool reverse_root,
                                 const InstanceTreeOptions& options = {});

/// The tree the turtle walked when the segments come in derivation order (vector input as
/// drawn): each segment hangs below the latest earlier segment that ends where it starts (the
/// turtle's current or a saved position), so overlapping copies keep their own branches.
/// Segments with no such predecessor (other than the first) are counted as unreached.
InstanceTree build_ordered_instance_tree(const std::vector<TreeSegment>& segments, double join_tolerance);

}  // namespace dg
