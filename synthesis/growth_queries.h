#pragma once
// The environment of one guide that answers the query modules of Open L-systems (Beneš et al.
// 2011, Table 2). Answers are written into the module: outputs first, then the arguments the
// successor gave (passed through unchanged):
//
//   ?DL ?DG ?DA (args...)  -> (found, d, beta, id, args...)   distance to the closest link edge,
//                                                             guide edge, or anything
//   ?NL ?NG ?NA (args...)  -> (found, d, id, args...)         distance ahead along the heading
//   ?X (delta, args...)    -> (found, id, delta, args...)     collision of the segment of length
//                                                             delta * scale ahead
//   ?seed (args...)        -> (x, y, heading, values...)      where the seed started
//
//   ?XS (delta, idin, args...) -> (found, id, delta, idin, args...)   like ?X; the tested
//                                                             segment gets the id idin
//
// Each has a variant with an id filter (Table 2's idtest): `?DLI ?DGI ?DAI ?NLI ?NGI ?NAI`
// take the id as their first argument, `?XI(delta, idtest, ...)` as its second,
// `?XSI(delta, idin, idtest, ...)` as its third; they see only links, guide edges or elements
// with that id (the layout of the answer is the same). Link queries (?DL ?NL ?DLI ?NLI) see
// only the links the environment says are available (free tokens, or reserved by the asker).
//
// found is 0 for nothing, 1 for a grown element, 2 for a guide edge and 3 for an edge that
// starts a link; d is in drawing units, beta in degrees (counter-clockwise positive, the turn
// toward the closest point); id is the link index (found 3), the guide edge index (found 2) or
// the element's id (found 1: the idin of the ?XS that tested it, else the number, from 0, of
// the seed in its guide that grew it), and -1 when nothing is found.

#include "grammar/module.h"
#include "synthesis/segment_grid.h"
#include "synthesis/turtle.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace dg {

/// An outgoing link's start edge inside the guide.
struct LinkEdge {
  Vec2 a = Vec2::Zero();
  Vec2 b = Vec2::Zero();
  std::size_t link = 0;
  std::size_t edge = 0;
};

/// What the queries of one guide see: its polygon, its outgoing link edges, its elements, and
/// which links the asking module may select (empty: all).
struct GuideEnvironment {
  const std::vector<Vec2>* polygon = nullptr;
  std::vector<LinkEdge> links;
  SegmentGrid* elements = nullptr;
  std::function<bool(std::size_t link)> available;
};

/// A ?X that crossed an edge holding links: the candidate links (in scene order), where it
/// crossed (parameter t along the edge from its first vertex) and the values it carries (its
/// arguments after delta).
struct EdgeCrossing {
  std::vector<std::size_t> links;
  double t = 0;
  std::vector<double> carried;
};

/// What an answer means for the tokens: the link a link query selected as its target, and
/// the crossing of a ?X.
struct QueryOutcome {
  std::optional<std::size_t> selected_link;
  std::optional<EdgeCrossing> crossing;
};

/// The seed a string grows from: its start (for ?seed), the values it carries, and the id its
/// elements get (the seed's number in its guide).
struct SeedStart {
  TurtlePose pose;
  std::vector<double> values;  ///< handed to ?seed (empty: keep the axiom's arguments)
  double element_id = 0;
};

/// True for the query symbols above.
bool is_growth_query(const std::string& symbol);

/// True for ?X, ?XI, ?XS and ?XSI.
bool is_collision_query(const std::string& symbol);

/// The distance a ?X (or ?XI, ?XS, ?XSI) module moves the turtle (its delta times the turtle scale): ?X stands for
/// the segment it tests, so the modules after it see the turtle at the segment's end. `answered`
/// says whether the outputs are already in front of delta. Throws InputError without delta.
double collision_query_length(const Module& module, bool answered, double scale);

/// The id an answered ?XS or ?XSI gives the element it tested (its idin), or nothing for
/// other modules.
std::optional<double> assigned_id(const Module& module);

/// Answers the fresh query `module` seen at `pose`. A ?X that finds nothing adds its segment to
/// the guide's elements (with its idin, else the seed's element id) so later queries of the
/// same step see it; a ?X that crosses a link edge returns the crossing; a link query that
/// finds a link returns it as selected. Throws InputError for an unknown query symbol.
QueryOutcome answer_query(Module& module, const TurtlePose& pose, GuideEnvironment& environment, const SeedStart& seed);

}  // namespace dg
