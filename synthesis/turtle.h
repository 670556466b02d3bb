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
/// declared otherwise). Throws InputError when a motif's path data is malformed.
TurtleOptions turtle_options(const TurtleSettings& settings);

/// Interprets `modules` and returns the strokes in derivation order. Throws InputError when a
/// `+`, `-` or `*` needs the default angle or scale and there is none, or a `]` has no `[`.
Drawing interpret(const std::vector<Module>& modules, const TurtleOptions& options);

}  // namespace dg
