#pragma once
// 2D turtle interpretation of a derived module string (conventions of the 2D corpus):
// y-up coordinates starting at (0, 0); heading in degrees counter-clockwise (0 = +x, 90 = up);
// `+` turns left, `-` right, `|` turns around; `F` (and every declared drawing symbol) draws a
// segment, `f` moves; `*` multiplies the turtle scale, which multiplies every later length and
// motif size; `[` / `]` push / pop the whole state; a motif symbol (`A` by default) places a
// copy of its motif. A module's first argument overrides the default (F(d), f(d), +(a), -(a),
// *(s)). Every other symbol is ignored.

#include "grammar/lsystem.h"
#include "grammar/module.h"
#include "synthesis/drawing.h"
#include "synthesis/path2d.h"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace dg {

/// Everything the turtle needs; see turtle_options() for the defaults.
struct TurtleOptions {
  std::optional<double> angle_deg;   ///< turn of `+`/`-` without argument (needed only when used)
  std::optional<double> scale;       ///< factor of `*` without argument (needed only when used)
  double step = 1;                   ///< length of `F`/`f` without argument
  double heading_deg = 0;            ///< start heading
  std::vector<std::string> draw_symbols{"F"};
  std::map<std::string, Path2d> motifs;  ///< symbol -> shape in the turtle's frame (x ahead, y left)
  double jitter_angle_deg = 0;  ///< each turn is changed by a uniform amount in [-j, j] degrees
  double jitter_scale = 0;      ///< each length, `*` factor and motif size is multiplied by 1 + [-j, j]
  std::uint64_t seed = 1;       ///< seeds the jitter
};

/// The motif that `A` places when the L-system declares none: the leaf of Št'ava et al. 2010,
/// 16 units long, SVG path data in the turtle's frame.
inline constexpr const char* default_motif = "M 0 0 C 3 6 11 7 16 0 C 11 -3 4 -3 0 0 Z";

/// Turtle options from an L-system's settings: its angle, scale, step (default 1), heading
/// (default 0), drawing symbols (default F) and motifs (parsed; `A` gets default_motif unless
/// it has a motif of its own or is a drawing symbol). Throws InputError when a motif's path data is malformed.
TurtleOptions turtle_options(const TurtleSettings& settings);

/// Where the turtle is: position (y-up drawing units), heading (degrees counter-clockwise) and
/// the scale that multiplies lengths.
struct TurtlePose {
  Vec2 position = Vec2::Zero();
  double heading_deg = 0;
  double scale = 1;
};

/// What walk_turtle reports; every callback may be left empty.
struct TurtleVisitor {
  /// A drawing symbol at module `index` drew the segment from -> to.
  std::function<void(std::size_t index, const Vec2& from, const Vec2& to)> segment;
  /// A motif symbol at module `index` placed `motif` at `pose`, `size` drawing units per path unit.
  std::function<void(std::size_t index, const Path2d& motif, const TurtlePose& pose, double size)> motif;
  /// Module `index` is a symbol the turtle does not act on; may change `pose` (e.g. move the
  /// turtle ahead without drawing, or put it where a known stretch of modules leaves it).
  std::function<void(std::size_t index, TurtlePose& pose)> other;
  /// Called before module `index` is acted on, with the pose then.
  std::function<void(std::size_t index, const TurtlePose& pose)> before;
};

/// Walks `modules` from `start` with the rules above (options.heading_deg is not used; the
/// start pose gives the heading), reports to `visitor` and returns the pose after the last
/// module. Throws like interpret().
TurtlePose walk_turtle(const std::vector<Module>& modules, const TurtleOptions& options, const TurtlePose& start,
                       const TurtleVisitor& visitor);

/// Interprets `modules` and returns the strokes in derivation order. Throws InputError when a
/// `+`, `-` or `*` needs the default angle or scale and there is none, or a `]` has no `[`.
Drawing interpret(const std::vector<Module>& modules, const TurtleOptions& options);

/// `motif` (turtle frame: x ahead, y left) placed at `pose`, scaled by `size`.
Path2d place_motif(const Path2d& motif, const TurtlePose& pose, double size);

}  // namespace dg
