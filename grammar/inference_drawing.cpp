#include "grammar/inference_drawing.h"

#include "grammar/grammar_length.h"

#include <string>

namespace dg {

std::optional<std::vector<TreeSegment>> straight_segments(const SvgDrawing& drawing) {
  std::vector<TreeSegment> segments;
  for (const SvgElement& element : drawing.elements) {
    if (element.polylines.size() != 1 || element.polylines.front().size() < 2) return std::nullopt;
    const auto& line = element.polylines.front();
    const Vec2 a(line.front().x(), -line.front().y()), b(line.back().x(), -line.back().y());
    const double length = (b - a).norm();
    if (length <= 0) return std::nullopt;
    const Vec2 along = (b - a) / length;
    for (const Vec2& p : line) {
      const Vec2 q(p.x() - a.x(), -p.y() - a.y());
      if (std::abs(q.x() * along.y() - q.y() * along.x()) > 1e-6 * length) return std::nullopt;
    }
    segments.push_back({a, b});
  }
  return segments;
}

InferredLSystem infer_drawing_lsystem(const SvgDrawing& drawing, const DrawingInferenceOptions& options) {
  std::optional<InferredLSystem> tree;
  if (const auto segments = straight_segments(drawing)) tree = infer_segment_lsystem(*segments, true, options.segments);
  const bool tree_has_rule = tree && tree->rules > 0;
  if (tree_has_rule && drawing.elements.size() > options.max_vector_elements) {
    tree->comparison = "instance tree " + std::to_string(grammar_length(tree->lsystem)) + ", vector not run (" +
                       std::to_string(drawing.elements.size()) + " elements)";
    return *tree;
  }
  InferredLSystem vector = infer_lsystem(drawing, options.vector);
  const std::size_t vector_length = grammar_length(vector.lsystem);
  if (!tree) {
    vector.comparison = "vector " + std::to_string(vector_length) + " (no instance tree)";
    return vector;
  }
  const std::size_t tree_length = grammar_length(tree->lsystem);
  const std::string comparison = "instance tree " + std::to_string(tree_length) + ", vector " + std::to_string(vector_length);
  InferredLSystem& chosen = tree_length <= vector_length ? *tree : vector;
  chosen.comparison = comparison;
  return chosen;
}

}  // namespace dg
