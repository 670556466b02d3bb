#pragma once
// An L-system: axiom, productions, and the defaults its turtle interpretation needs.

#include "grammar/module.h"
#include "grammar/production.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace dg {

/// How the turtle reads the derived string, as far as the L-system itself says. Everything
/// optional may be absent; the interpreter then uses its own defaults.
struct TurtleSettings {
  std::optional<double> angle_deg;    ///< turn of `+` / `-` without argument, degrees
  std::optional<double> scale;        ///< factor of `*` without argument
  std::optional<double> step;         ///< length of `F` / `f` without argument, drawing units
  std::optional<double> heading_deg;  ///< start heading, degrees counter-clockwise (0 = +x, 90 = up)
  std::vector<std::string> draw_symbols;     ///< symbols that draw like `F` (empty: just `F`)
  std::map<std::string, std::string> motifs;  ///< symbol -> SVG path data in the turtle's frame

  friend bool operator==(const TurtleSettings&, const TurtleSettings&) = default;
};

/// Axiom, productions (in file order; the order matters only for printing) and turtle settings.
/// `iterations` is the default number of derivation steps; absent means "rewrite until no
/// production applies".
struct LSystem {
  std::vector<Module> axiom;
  std::vector<Production> productions;
  std::optional<int> iterations;
  TurtleSettings turtle;

  friend bool operator==(const LSystem&, const LSystem&) = default;
};

}  // namespace dg
