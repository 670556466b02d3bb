#pragma once
// Whether two productions of a context-free grammar are the same: an exemplar repeats a part
// with a different triangulation here and there, and a production cut from such a copy offers
// no variation.

#include "grammar/context_free.h"

namespace dg {

/// True when `a` and `b` are equal up to `tolerance` (model units): the same left side, the
/// same child slots (non-terminal, exemplar production, placement within tolerance) and
/// terminals of the same surface however they are triangulated (same_surface), or, for point
/// clouds, however they are sampled (same_points).
bool same_production(const ShapeProduction& a, const ShapeProduction& b, double tolerance);

}  // namespace dg
