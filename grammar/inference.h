#pragma once
// Inverse procedural modeling of 2D vector drawings by L-systems (Št'ava et al. 2010): terminals
// by inverse instancing, rules from clusters in the transformation spaces chosen by importance,
// built into a hierarchy until one axiom is left, then cleaned of trivial transforms.

#include "geometry/svg_reader.h"
#include "grammar/inference_clusters.h"
#include "grammar/inference_terminals.h"
#include "grammar/lsystem.h"

#include <cstddef>
#include <string>

namespace dg {

/// All knobs of the inference; the defaults suit clean drawings and light jitter.
struct InferenceOptions {
  SimilarityOptions similarity;  ///< element similarity (threshold 0.6)
  ClusterOptions clusters;       ///< transformation spaces, importance weights
  int max_rules = 200;           ///< the hierarchy stops after this many rules; what is left goes into the axiom
  int proximity_samples = 16;    ///< points per element used for proximity (h)
  int group_samples = 64;        ///< most points kept per rule instance
};

/// Seconds spent per stage.
struct InferenceTimings {
  double instancing_s = 0;  ///< similarity and inverse instancing
  double rules_s = 0;       ///< clustering, rule selection and hierarchy
  double total_s = 0;
};

/// The inferred L-system and where its turtle starts on the input canvas.
struct InferredLSystem {
  LSystem lsystem;         ///< text-ready: rules, heading, step or motifs
  std::string text;        ///< lsystem in the text form
  Vec2 start_svg = Vec2::Zero();  ///< SVG coordinates (y down) of the turtle's start
  std::size_t elements = 0;       ///< input elements used (without extent-less ones)
  std::size_t terminals = 0;
  std::size_t rules = 0;          ///< rules created by the hierarchy
  std::string method = "vector";  ///< "vector" (Št'ava 2010) or "instance tree" (Guo 2020)
  std::string comparison;         ///< grammar lengths of the methods that were tried, e.g. "instance tree 17, vector 292"
  InferenceTimings timings;
};

/// Infers an L-system whose derivation redraws `drawing`: each element becomes an instance of a
/// terminal; sequence and branching rules are chosen greedily by importance and their instances
/// replaced by non-terminals until no rule absorbs anything; the remaining nodes form the axiom
/// (relative transforms from the first one). Throws InputError when the drawing has no element
/// with extent.
InferredLSystem infer_lsystem(const SvgDrawing& drawing, const InferenceOptions& options = {});

}  // namespace dg
