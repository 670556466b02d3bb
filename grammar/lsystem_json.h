#pragma once
// The L-system JSON form, the same as the `lsystem` field of the 2D corpus:
//   {"axiom": "P(336)", "rules": {"P(m) : m>0": "A f(27.5) *(0.993) +(8.5) P(m-1)",
//    "P(m) : m==0": "", "F": ["(0.5) F[+F]F", "(0.5) F[-F]F"]},
//    "iterations": 337, "angle": 8.5, "scale": 0.993, "scale_ratio": 1.00705, "step": null}
// plus optional "heading" (degrees), "draw" (symbols that draw like F) and "motifs"
// ({"A": "M 0 0 L 9 0"}). A rule value is one right side or an array of stochastic alternatives.

#include "grammar/lsystem.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace dg {

/// Reads the JSON form. Also accepts a whole corpus case (an object with an "lsystem" field):
/// then its "symbols" (those that "draw ..." and those that "place one copy of motif ..."),
/// "motif.local_path" and "turtle.start_heading_deg" fill the turtle settings.
/// Errors are InputError "source: problem" naming the rule when one is malformed.
LSystem lsystem_from_json(const nlohmann::ordered_json& json, const std::string& source);

/// Reads and parses a JSON file (either form above).
LSystem read_lsystem_json(const std::filesystem::path& path);

/// The JSON form of `system` (rules in production order, alternatives of one left side as an
/// array); lsystem_from_json reads it back to an equal LSystem.
nlohmann::ordered_json lsystem_to_json(const LSystem& system);

}  // namespace dg
