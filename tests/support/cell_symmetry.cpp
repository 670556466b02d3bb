#include "support/cell_symmetry.h"

namespace dg::test {

double symmetric_fraction(const PreparedModel& prepared, const RigidTransform& t, const RegionOptions& options) {
  const CellMatcher matcher(prepared.surface, nullptr, options);
  const RigidTransform back = t.inverse();
  std::size_t symmetric = 0;
  for (std::uint32_t c = 0; c < prepared.surface.cell_count(); ++c) symmetric += matcher.symmetric(c, t, back) ? 1 : 0;
  return static_cast<double>(symmetric) / static_cast<double>(prepared.surface.cell_count());
}

}  // namespace dg::test
