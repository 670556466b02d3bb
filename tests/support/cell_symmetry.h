#pragma once
// Cell-level symmetry checks for tests of the matcher.

#include "geometry/prepared_model.h"
#include "symmetry/symmetric_region.h"

namespace dg::test {

/// Fraction of the surface cells that `t` maps onto the surface and back (CellMatcher::symmetric).
double symmetric_fraction(const PreparedModel& prepared, const RigidTransform& t, const RegionOptions& options = {});

}  // namespace dg::test
