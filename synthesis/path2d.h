#pragma once
// 2D paths of straight and cubic Bézier pieces: motif shapes and drawn strokes. Read from and
// written as SVG path data (M, L, H, V, C, Z in absolute and relative form).

#include "geometry/types.h"

#include <array>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace dg {

/// One path command with absolute points: Move and Line use points[0]; Cubic uses the two
/// control points and the end point, in that order; Close uses none.
struct PathCommand {
  enum class Type { Move, Line, Cubic, Close };
  Type type = Type::Move;
  std::array<Vec2, 3> points{Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};
};

/// A path: a list of commands that starts with a Move.
struct Path2d {
  std::vector<PathCommand> commands;
};

/// Parses SVG path data (M m L l H h V v C c Z z, implicit repeats). Throws InputError
/// "path data: problem" on malformed text or an unsupported command.
Path2d parse_svg_path(std::string_view data);

/// A copy of `path` with every point (control points included) mapped by `map`; exact for
/// affine maps, which is all that callers use.
Path2d map_path(const Path2d& path, const std::function<Vec2(const Vec2&)>& map);

/// Polylines approximating the path, one per subpath; Bézier pieces are split into straight
/// pieces no longer than about `max_piece` (same units as the path). Close adds the closing piece.
std::vector<std::vector<Vec2>> flatten_path(const Path2d& path, double max_piece);

/// Grows [low, high] to contain every point of the path (control points included).
void add_path_bounds(const Path2d& path, Vec2& low, Vec2& high);

/// SVG path data of `path` with numbers rounded to `decimals` places (`M 1.5 2 L 3 4 Z`).
std::string format_svg_path(const Path2d& path, int decimals);

/// `value` rounded to `decimals` places without trailing zeros (`141.746`, `2`, `-0.5`).
std::string format_svg_number(double value, int decimals);

}  // namespace dg
