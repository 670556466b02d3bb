#pragma once
// Rendering a turtle drawing to SVG (one element per stroke) and PNG (anti-aliased lines),
// framed like the 2D corpus: page fitted to the drawing with a margin, y pointing down.

#include "geometry/image.h"
#include "synthesis/drawing.h"

#include <filesystem>
#include <string>

namespace dg {

/// Appearance of a rendered drawing.
struct RenderOptions {
  double margin_fraction = 0.02;  ///< margin on every side, as a fraction of the drawing's longer side
  int long_side_px = 512;         ///< PNG: pixels along the page's longer side
  double line_width_px = 1.5;     ///< stroke width in PNG pixels (SVG: the same at long_side_px)
  int decimals = 3;               ///< SVG: decimal places of coordinates
};

/// SVG text: viewBox in drawing units, one <path> per stroke in stroke order, style set once
/// on the root element.
std::string format_svg(const Drawing& drawing, const RenderOptions& options = {});

/// The drawing rasterized black on white; the longer page side has options.long_side_px pixels.
Image rasterize(const Drawing& drawing, const RenderOptions& options = {});

/// Writes the SVG (format_svg) atomically; InputError when the file cannot be written.
void write_svg(const std::filesystem::path& path, const Drawing& drawing, const RenderOptions& options = {});

}  // namespace dg
