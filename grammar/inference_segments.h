#pragma once
// L-system inference for drawings made of straight segments (Guo et al. 2020 §4.2): instance
// tree -> bracketed turtle string -> compaction by repeated blocks -> `F -> block` with the
// turtle's angle, scale, step and heading. The root is not known, so a few candidate roots
// (the first segment, then segments where the drawing starts or at its extreme points) are tried
// and the shortest grammar is kept.

#include "grammar/inference.h"
#include "grammar/instance_tree.h"

#include <optional>
#include <vector>

namespace dg {

/// Knobs of the segment inference.
struct SegmentInferenceOptions {
  double join_fraction = 1e-4;      ///< end points closer than this fraction of the diagonal are joined
  int max_roots = 12;               ///< candidate roots tried (each in both directions when undirected)
  double max_turn_error_deg = 6;    ///< a tree whose turns miss multiples of δ by more (or by 0.4 δ) is rejected
  double max_length_error = 0.2;    ///< ... or whose lengths miss step * s^j by more (relative)
  std::size_t max_block = 200;      ///< longest rule successor tried
  double snap_angle_deg = 0;        ///< δ within this of 360/k (k = 3..36) becomes 360/k (pixel input:
                                    ///< a pixel-measured δ off by half a degree no longer closes curves)
};

/// Infers `F -> block` for segments in y-up units. `directed`: each segment is walked from start
/// to end (vector input); otherwise directions come from the tree (pixel input). Nothing when no
/// candidate root reaches every segment with turns and lengths within the tolerances.
std::optional<InferredLSystem> infer_segment_lsystem(const std::vector<TreeSegment>& segments, bool directed,
                                                     const SegmentInferenceOptions& options = {});

}  // namespace dg
