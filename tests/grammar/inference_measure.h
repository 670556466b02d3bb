#pragma once
// Measures of an inferred L-system against a corpus drawing, shared by the inference tests:
// symmetric Hausdorff distance between the input strokes and the re-derivation (points sampled
// along all strokes, grid search), in the drawing's SVG units.

#include "geometry/svg_reader.h"
#include "grammar/inference.h"

#include <filesystem>
#include <vector>

namespace dg::test {

/// The 2D corpus folder (../shared/corpus/lsystems next to the repository).
std::filesystem::path lsystem_corpus_dir();

/// Corpus case ids (file stems with .svg and .json), sorted.
std::vector<std::string> lsystem_corpus_cases();

/// Points every `spacing` units along every polyline of the drawing (SVG units, y down).
std::vector<Vec2> drawing_points(const SvgDrawing& drawing, double spacing);

/// Bounding-box diagonal of the points.
double diagonal_of(const std::vector<Vec2>& points);

/// The inferred system re-derived and placed at its start_svg, divided by `units_per_svg_unit`
/// (1 for vector input, px_per_unit for pixel input), as points every `spacing` SVG units.
std::vector<Vec2> rederived_points(const InferredLSystem& inferred, double spacing, double units_per_svg_unit = 1);

/// Symmetric Hausdorff distance of two point sets (`cell`: grid size of the search).
double symmetric_hausdorff(const std::vector<Vec2>& a, const std::vector<Vec2>& b, double cell);

}  // namespace dg::test
