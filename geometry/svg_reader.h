#pragma once
// Reading 2D vector drawings from SVG: every drawn element (path, line, polyline, polygon, rect,
// circle, ellipse) becomes a list of polylines in absolute SVG user coordinates (y down), with
// the transforms of its enclosing groups and its own `transform` attribute applied. Curves and
// arcs are flattened. A small hand-written XML tokenizer; no external dependency.

#include "geometry/types.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace dg {

/// One drawn SVG element, flattened.
struct SvgElement {
  std::string tag;                           ///< element name: "path", "line", "rect", ...
  std::size_t line = 0;                      ///< 1-based line of its start tag
  std::vector<std::vector<Vec2>> polylines;  ///< one per subpath, absolute SVG user units (y down);
                                             ///< a closed subpath repeats its first point
};

/// The drawing: elements in document order and the canvas size (0 when not given).
struct SvgDrawing {
  std::vector<SvgElement> elements;
  double width = 0;   ///< viewBox width, else the `width` attribute, in user units
  double height = 0;  ///< viewBox height, else the `height` attribute
};

/// How curves are flattened.
struct SvgReadOptions {
  double max_piece = 0.25;      ///< longest straight piece a curve or arc is split into (user units)
  int min_pieces_per_curve = 16;   ///< curves keep their shape however small they are drawn
  int max_pieces_per_curve = 256;  ///< upper bound of pieces per curve segment or arc
};

/// 2x3 affine map of SVG transforms: p' = linear * p + offset.
struct Affine2 {
  Eigen::Matrix2d linear = Eigen::Matrix2d::Identity();
  Vec2 offset = Vec2::Zero();
  Vec2 operator()(const Vec2& p) const { return linear * p + offset; }
  /// This map applied after `inner`.
  Affine2 then_after(const Affine2& inner) const {
    return Affine2{linear * inner.linear, linear * inner.offset + offset};
  }
};

/// Parses an SVG `transform` attribute list (matrix, translate, scale, rotate with optional
/// centre, skewX, skewY; angles in degrees); the leftmost transform is applied last, as in SVG.
/// Throws InputError "transform: problem" on malformed text.
Affine2 parse_svg_transform(std::string_view text);

/// Flattens SVG path data (M L H V C S Q T A Z, absolute and relative, implicit repeats) into
/// polylines, one per subpath, in the path's own coordinates. Throws InputError
/// "path data: problem" on malformed text.
std::vector<std::vector<Vec2>> flatten_svg_path_data(std::string_view data, const SvgReadOptions& options = {});

/// Parses SVG text. `source` names the input in errors, which read "source:line: problem"
/// (InputError): malformed XML, unbalanced tags, bad numbers, path data or transforms.
/// Elements inside defs, symbol, clipPath, mask, pattern, marker and text are not drawn unless a
/// <use href="#id" x y> (or xlink:href) draws them; unknown ids and cyclic references are errors.
SvgDrawing parse_svg(std::string_view text, const std::string& source, const SvgReadOptions& options = {});

/// Reads and parses an SVG file; InputError "path: cannot read" when it cannot be read.
SvgDrawing read_svg(const std::filesystem::path& path, const SvgReadOptions& options = {});

}  // namespace dg
