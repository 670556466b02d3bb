#pragma once
// A guided-growth scene (Beneš et al. 2011): guides (closed polygons) that each hold at most
// one Open L-system and any number of seeds, and oriented links between guide edges that carry
// tokens. Coordinates are y-up drawing units; angles are degrees counter-clockwise.

#include "geometry/types.h"
#include "grammar/lsystem.h"

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace dg {

/// An explicit seed: where an L-system starts, its heading, and values handed to its `?seed`.
struct GuideSeed {
  Vec2 position = Vec2::Zero();
  double heading_deg = 90;
  std::vector<double> parameters;
};

/// A guide: a closed polygon (vertex i to vertex i+1 is edge i; the last edge closes it), the
/// L-system it runs (index into GrowthScene::lsystems) and its explicit seeds.
struct Guide {
  std::string name;
  std::vector<Vec2> polygon;
  std::optional<std::size_t> lsystem;
  std::vector<GuideSeed> seeds;
};

/// An oriented link from edge `from_edge` of guide `from_guide` to edge `to_edge` of guide
/// `to_guide`, with `tokens` messages it can send. A turtle crossing the start edge at
/// parameter t (0 at the edge's first vertex) seeds the target guide at parameter 1 - t of the
/// target edge (so edges shared by snapped guides map point to point), heading along the
/// target edge's inward normal turned by `angle_deg`.
struct GuideLink {
  std::size_t from_guide = 0;
  std::size_t from_edge = 0;
  std::size_t to_guide = 0;
  std::size_t to_edge = 0;
  int tokens = 1;
  double angle_deg = 0;
};

/// A named L-system of the scene.
struct GrowthLSystem {
  std::string name;
  LSystem system;
};

/// A stiff spring between a vertex of one guide and a vertex of another (mass-spring editing).
struct GuideSpring {
  std::size_t guide_a = 0, vertex_a = 0, guide_b = 0, vertex_b = 0;
};

/// Mass-spring settings (Beneš et al. §4.2): edge springs, diagonal springs inside each guide,
/// and stiff springs between guides; stiffness values are relative weights.
struct SpringSettings {
  double edge_stiffness = 1;
  double diagonal_stiffness = 0.5;
  double link_stiffness = 20;
  int iterations = 500;
  std::vector<GuideSpring> springs;  ///< extra stiff springs between guides
  bool link_springs = true;          ///< also stiff springs across every link (its edge ends)
  std::vector<std::pair<std::size_t, std::size_t>> pinned;  ///< (guide, vertex) that never move
};

/// One editing operation on the guides.
struct GuideEdit {
  enum class Kind { Translate, Rotate, Scale, MoveVertex, Snap };
  Kind kind = Kind::Translate;
  std::size_t guide = 0;
  Vec2 offset = Vec2::Zero();   ///< Translate: the shift; MoveVertex: the vertex's new position
  double angle_deg = 0;         ///< Rotate: about the guide's vertex centroid
  double factor = 1;            ///< Scale: about the guide's vertex centroid
  std::size_t vertex = 0;       ///< MoveVertex: which vertex (mass-spring drag)
  std::size_t target = 0;       ///< Snap: move `guide` so its edge `edge` lies on edge `target_edge` of `target`
  std::size_t edge = 0;
  std::size_t target_edge = 0;
};

/// Limits that stop runaway growth with a LimitError.
struct GrowthLimits {
  int max_steps = 2000;                 ///< parallel derivation steps of the whole scene
  std::size_t max_elements = 2'000'000;  ///< drawn elements of the whole scene
  std::size_t max_modules = 2'000'000;   ///< modules of one seed's string
};

/// The whole scene.
struct GrowthScene {
  std::vector<Guide> guides;
  std::vector<GuideLink> links;
  std::vector<GrowthLSystem> lsystems;
  SpringSettings springs;
  std::vector<GuideEdit> edits;
  GrowthLimits limits;
};

}  // namespace dg
