#pragma once
// Element similarity and inverse instancing (Št'ava et al. 2010 §4.1-§4.2): the drawn elements
// are grouped into terminal symbols, each instance keeping its frame (position, rotation, scale).

#include "grammar/inference_transform.h"

#include <cstddef>
#include <string>
#include <vector>

namespace dg {

/// One drawn element: its polylines in y-up drawing units.
using ElementShape = std::vector<std::vector<Vec2>>;

/// Options of the similarity test.
struct SimilarityOptions {
  int samples = 32;                   ///< uniform samples per element
  double threshold = 0.6;             ///< elements are similar when their similarity exceeds this
  double match_tolerance = 0.05;      ///< a sample matches within this fraction of the element diameter
  double vote_angle_deg = 10;         ///< mean shift bandwidth of the rotation votes
};

/// A terminal symbol: either the segment `F` (every single straight segment, drawn with length
/// `step`) or a motif placed by a letter, with its shape in the representative's frame
/// (x ahead, y left, origin at the turtle; the representative has scale 1).
struct Terminal {
  std::string symbol;
  bool segment = false;
  double step = 0;      ///< segments: length of the representative
  ElementShape motif;   ///< motifs: the representative's polylines in its own frame
};

/// One placed copy of a terminal.
struct TerminalInstance {
  std::size_t terminal = 0;  ///< index into Instancing::terminals
  std::size_t element = 0;   ///< index of the input element
  InstanceFrame frame;
  double similarity = 1;     ///< similarity to the representative (1 for segments)
};

/// Terminals and their instances, in a canonical order that does not depend on the order of
/// the input elements (by position, then angle).
struct Instancing {
  std::vector<Terminal> terminals;
  std::vector<TerminalInstance> instances;
  std::size_t skipped = 0;  ///< elements without extent (a single point), left out
};

/// `count` points spread uniformly by arc length over all polylines of the element.
std::vector<Vec2> sample_points(const ElementShape& shape, int count);

/// Similarity of two elements in [0, 1] as in §4.1: both are sampled and normalized in scale;
/// transforms that map samples of `a` onto samples of `b` with similar curvature vote, mean shift
/// finds the strongest transform, and the similarity is the share of b's samples it explains.
double element_similarity(const ElementShape& a, const ElementShape& b, const SimilarityOptions& options = {});

/// Groups the elements into terminals (symbols F for straight segments, then A, B, C, ... skipping
/// letters used by the turtle and the rules) and computes every instance's frame: origin at the
/// element's first point, rotation of the direction to its farthest point (segments: absolute
/// direction; motifs: relative to the representative), scale by that distance.
Instancing inverse_instancing(const std::vector<ElementShape>& elements, const SimilarityOptions& options = {});

}  // namespace dg
