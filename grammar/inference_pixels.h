#pragma once
// L-system inference from pixel images (a classical front end instead of Guo et al.'s CNN):
// Otsu binarization, Zhang–Suen skeleton, stroke graph, straight pieces split at corners. Then
//  - segment drawings: the pieces (optionally cut into equal steps, since collinear `F F` merge
//    into one straight run in pixels) go through the instance tree and compaction;
//  - motif drawings: each connected stroke component is one element for the vector
//    (Št'ava) inference, which groups repeated templates into terminals;
//  - the pieces as elements of the vector inference, as a fallback.
// The shortest grammar wins. Coordinates are pixels (x right, y down on the canvas; the
// L-system's turtle is y-up as always).

#include "geometry/image.h"
#include "grammar/inference_drawing.h"

#include <cstddef>

namespace dg {

/// Knobs of the pixel front end.
struct PixelInferenceOptions {
  DrawingInferenceOptions drawing;
  double join_px = 3;                ///< piece ends closer than this many 512ths of the diagonal are one point
                                     ///< (bridges skeleton gaps at junctions)
  double corner_tolerance_px = 1.2;  ///< Douglas–Peucker tolerance of the straight pieces
  std::size_t max_components = 2500;  ///< the vector path on components runs for 4 to this many components
  double max_component_share = 0.2;  ///< ... when no component holds more than this share of the skeleton
  std::size_t max_vector_pieces = 250;  ///< the vector path on pieces runs up to this many pieces
  int max_component_rules = 20;      ///< rule budget of the vector path on components (each rule re-runs the
                                     ///< cluster analysis; pixel templates vary more than vector ones)
  double snap_angle_deg = 1;         ///< δ within this of 360/k becomes 360/k (SegmentInferenceOptions)
  double max_turn_error_deg = 15;    ///< pixel corners are off by a pixel: looser than for vectors
  double max_length_error = 0.35;    ///< (both also bounded by the segment options' own values)
  double min_piece_px = 2.5;         ///< inner pieces shorter than this or 0.4 times the median piece are
                                     ///< corners the skeleton cut off and are restored (fit_polyline); shorter
                                     ///< pieces do not count for the step estimate
};

/// What the front end found, for reports.
struct PixelFrontEnd {
  std::size_t ink_pixels = 0;
  std::size_t skeleton_pixels = 0;
  std::size_t nodes = 0;
  std::size_t chains = 0;
  std::size_t pieces = 0;      ///< straight pieces
  std::size_t components = 0;  ///< connected stroke groups
  double seconds = 0;
};

/// The inferred L-system and the front end's counts.
struct PixelInference {
  InferredLSystem inferred;  ///< start_svg in pixel coordinates
  PixelFrontEnd front_end;
};

/// Infers an L-system that redraws the strokes of `image` (dark on light). Throws InputError
/// when the image has no strokes.
PixelInference infer_pixel_lsystem(const Image& image, const PixelInferenceOptions& options = {});

}  // namespace dg
