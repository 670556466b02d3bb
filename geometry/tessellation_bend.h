#pragma once
// How far a tessellated curved surface or curve turns from one facet (or feature edge) to the
// next. Exact plane matching fails on such geometry when a motion does not share the
// tessellation step (a handrail in 8-degree segments under a 22.5-degree screw): mapped facets
// land tilted by up to one step on the facets there.

#include "geometry/feature_edges.h"
#include "geometry/mesh.h"

#include <span>
#include <vector>

namespace dg {

/// Per triangle: the largest angle (degrees) between its normal and a neighbour's across an edge
/// that is not in `features` (smooth edges only; sorted by (v0, v1) as find_feature_edges gives
/// them). 0 for a triangle whose smooth neighbours all lie in its plane.
std::vector<double> triangle_bend_degrees(const TriangleMesh& mesh, std::span<const FeatureEdge> features);

/// Per feature edge: the largest angle (degrees) between its direction and a feature edge of the
/// same kind continuing it at either end, counting only continuations that turn by less than
/// `max_turn_degrees` (a polyline tessellating a curve, not a corner). 0 for straight runs.
std::vector<double> feature_edge_bend_degrees(const TriangleMesh& mesh, std::span<const FeatureEdge> features,
                                              double max_turn_degrees);

}  // namespace dg
