#include "grammar/inference_pixels.h"

#include "geometry/errors.h"
#include "geometry/skeleton.h"
#include "geometry/stroke_graph.h"
#include "grammar/grammar_length.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

namespace dg {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Length of one turtle step: the median of the shortest cluster of piece lengths (sorted,
// split at gaps over 15 %) holding at least 5 % of the pieces.
double step_length(std::vector<double> lengths, double least) {
  std::sort(lengths.begin(), lengths.end());
  std::vector<double> kept;
  for (double l : lengths)
    if (l >= least) kept.push_back(l);
  if (kept.empty()) return 0;
  for (std::size_t begin = 0; begin < kept.size();) {
    std::size_t end = begin + 1;
    while (end < kept.size() && kept[end] <= kept[end - 1] * 1.15) ++end;
    if ((end - begin) * 20 >= kept.size()) return kept[(begin + end) / 2];
    begin = end;
  }
  return kept.front();
}

// Pieces cut into `round(length / step)` equal parts (y-up).
std::vector<TreeSegment> cut_into_steps(const std::vector<TreeSegment>& pieces, double step) {
  std::vector<TreeSegment> out;
  for (const TreeSegment& piece : pieces) {
    const int parts = step > 0 ? std::max(1, static_cast<int>(std::lround((piece.end - piece.start).norm() / step))) : 1;
    for (int k = 0; k < parts; ++k)
      out.push_back({piece.start + (piece.end - piece.start) * (static_cast<double>(k) / parts),
                     piece.start + (piece.end - piece.start) * (static_cast<double>(k + 1) / parts)});
  }
  return out;
}

SvgElement element_of(std::vector<std::vector<Vec2>> polylines) {
  SvgElement element;
  element.tag = "path";
  element.polylines = std::move(polylines);
  return element;
}

void keep_shorter(std::optional<InferredLSystem>& best, InferredLSystem candidate, std::string& comparison, const std::string& name) {
  const std::size_t length = grammar_length(candidate.lsystem);
  comparison += (comparison.empty() ? "" : ", ") + name + " " + std::to_string(length);
  if (!best || length < grammar_length(best->lsystem)) best = std::move(candidate);
}

}  // namespace

PixelInference infer_pixel_lsystem(const Image& image, const PixelInferenceOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  PixelInference result;
  PixelFrontEnd& front = result.front_end;
  const BinaryImage ink = binarize(image);
  front.ink_pixels = static_cast<std::size_t>(std::count(ink.ink.begin(), ink.ink.end(), 1));
  if (front.ink_pixels == 0) throw InputError("the image has no strokes (one tone only)");
  const BinaryImage skeleton = thin(ink);
  front.skeleton_pixels = static_cast<std::size_t>(std::count(skeleton.ink.begin(), skeleton.ink.end(), 1));
  const StrokeGraph graph = trace_strokes(skeleton);
  front.nodes = graph.nodes.size();
  front.chains = graph.chains.size();
  // Straight pieces, y-up.
  std::vector<TreeSegment> pieces;
  std::vector<double> lengths;
  std::vector<double> rough;
  for (const StrokeChain& chain : graph.chains) {
    const std::vector<std::size_t> corners = chain_corners(chain.points, options.corner_tolerance_px);
    for (std::size_t k = 1; k < corners.size(); ++k) rough.push_back((chain.points[corners[k]] - chain.points[corners[k - 1]]).norm());
  }
  std::sort(rough.begin(), rough.end());
  const double min_piece = std::max(options.min_piece_px, rough.empty() ? 0.0 : 0.4 * rough[rough.size() / 2]);
  std::vector<int> degree(graph.nodes.size(), 0);
  for (const StrokeChain& chain : graph.chains) ++degree[chain.from], ++degree[chain.to];
  for (const StrokeChain& chain : graph.chains) {
    const bool closed = chain.from == chain.to && degree[chain.from] == 2;
    const std::vector<Vec2> corners = fit_polyline(chain.points, closed, options.corner_tolerance_px, min_piece);
    for (std::size_t k = 1; k < corners.size(); ++k) {
      const Vec2 a = corners[k - 1], b = corners[k];
      if ((b - a).norm() < 1e-9) continue;
      pieces.push_back({Vec2(a.x(), -a.y()), Vec2(b.x(), -b.y())});
      lengths.push_back((b - a).norm());
    }
  }
  front.pieces = pieces.size();
  const std::vector<std::vector<std::size_t>> components = stroke_components(graph);
  front.components = components.size();
  front.seconds = seconds_since(start);
  if (pieces.empty()) throw InputError("the image has no strokes longer than a pixel");

  std::optional<InferredLSystem> best;
  std::string comparison;
  // Segment drawings: pieces as they are, and cut into equal steps.
  SegmentInferenceOptions segment_options = options.drawing.segments;
  segment_options.join_fraction = std::max(segment_options.join_fraction, options.join_px / 512);
  segment_options.snap_angle_deg = std::max(segment_options.snap_angle_deg, options.snap_angle_deg);
  segment_options.max_turn_error_deg = std::max(segment_options.max_turn_error_deg, options.max_turn_error_deg);
  segment_options.max_length_error = std::max(segment_options.max_length_error, options.max_length_error);
  if (auto tree = infer_segment_lsystem(pieces, false, segment_options)) keep_shorter(best, std::move(*tree), comparison, "instance tree");
  const double step = step_length(lengths, options.min_piece_px);
  const std::vector<TreeSegment> steps = cut_into_steps(pieces, step);
  if (steps.size() != pieces.size())
    if (auto tree = infer_segment_lsystem(steps, false, segment_options))
      keep_shorter(best, std::move(*tree), comparison, "instance tree on steps");
  const bool tree_has_rule = best && best->rules > 0;
  // Motif drawings: every stroke component is one element; specks (components spanning fewer
  // than min_piece_px) are left out.
  std::vector<std::vector<std::size_t>> motifs;
  std::size_t all_points = 0, largest = 0;
  for (const auto& component : components) {
    std::size_t points = 0;
    Vec2 low = graph.chains[component.front()].points.front(), high = low;
    for (std::size_t c : component) {
      points += graph.chains[c].points.size();
      for (const Vec2& p : graph.chains[c].points) low = low.cwiseMin(p), high = high.cwiseMax(p);
    }
    if ((high - low).norm() < options.min_piece_px) continue;
    motifs.push_back(component);
    all_points += points;
    largest = std::max(largest, points);
  }
  const bool motif_like = motifs.size() >= 4 && motifs.size() <= options.max_components &&
                          static_cast<double>(largest) <= options.max_component_share * static_cast<double>(all_points);
  if (motif_like) {
    SvgDrawing drawing;
    for (const auto& component : motifs) {
      std::vector<std::vector<Vec2>> polylines;
      for (std::size_t c : component) {
        std::vector<Vec2> simplified;
        for (std::size_t k : chain_corners(graph.chains[c].points, 0.5)) simplified.push_back(graph.chains[c].points[k]);
        polylines.push_back(std::move(simplified));
      }
      drawing.elements.push_back(element_of(std::move(polylines)));
    }
    InferenceOptions vector = options.drawing.vector;
    vector.max_rules = std::min(vector.max_rules, options.max_component_rules);
    keep_shorter(best, infer_lsystem(drawing, vector), comparison, "vector on components");
  }
  // Fallback: every straight piece an element of the vector inference.
  if (!tree_has_rule && pieces.size() <= options.max_vector_pieces) {
    SvgDrawing drawing;
    for (const TreeSegment& piece : pieces)
      drawing.elements.push_back(element_of({{Vec2(piece.start.x(), -piece.start.y()), Vec2(piece.end.x(), -piece.end.y())}}));
    keep_shorter(best, infer_lsystem(drawing, options.drawing.vector), comparison, "vector on pieces");
  }
  if (!best)
    throw InputError("no inference path applies: the " + std::to_string(pieces.size()) + " straight pieces form no turtle tree within the tolerances, and there are too many pieces (> " +
                     std::to_string(options.max_vector_pieces) + ") or components (> " + std::to_string(options.max_components) + ") for the vector path");
  result.inferred = std::move(*best);
  result.inferred.comparison = comparison;
  result.inferred.timings.total_s = seconds_since(start);
  return result;
}

}  // namespace dg
