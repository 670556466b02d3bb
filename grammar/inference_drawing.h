#pragma once
// One entry point for vector drawings: the instance-tree path (Guo et al. 2020) for drawings of
// straight segments and the transformation-space path (Št'ava et al. 2010) for everything, and
// the shorter grammar of the two.

#include "geometry/svg_reader.h"
#include "grammar/inference.h"
#include "grammar/inference_segments.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace dg {

/// Options of both paths and of the choice between them.
struct DrawingInferenceOptions {
  InferenceOptions vector;             ///< Št'ava path
  SegmentInferenceOptions segments;    ///< Guo path
  std::size_t max_vector_elements = 1000;  ///< when the Guo path found a rule, the Št'ava path
                                           ///< runs only up to this many elements (it is slow on
                                           ///< large segment drawings and never shorter there)
};

/// The elements as straight segments in y-up units (first to last point), or nothing when some
/// element is not one straight polyline (within 1e-6 of its length).
std::optional<std::vector<TreeSegment>> straight_segments(const SvgDrawing& drawing);

/// Infers with both paths where they apply and returns the shorter grammar (by grammar_length;
/// ties go to the instance tree), with `comparison` naming both lengths. Throws InputError as
/// infer_lsystem does.
InferredLSystem infer_drawing_lsystem(const SvgDrawing& drawing, const DrawingInferenceOptions& options = {});

}  // namespace dg
