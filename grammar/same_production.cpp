#include "grammar/same_production.h"

#include "geometry/same_surface.h"

namespace dg {

bool same_production(const ShapeProduction& a, const ShapeProduction& b, double tolerance) {
  if (a.lhs != b.lhs || a.children.size() != b.children.size() || a.terminal.triangles.empty() != b.terminal.triangles.empty() ||
      a.terminal_points.positions.empty() != b.terminal_points.positions.empty())
    return false;
  for (std::size_t i = 0; i < a.children.size(); ++i) {
    const ChildSlot &x = a.children[i], &y = b.children[i];
    if (x.nonterminal != y.nonterminal || x.original_production != y.original_production ||
        !same_motion(x.placement, y.placement, Vec3::Zero(), tolerance))
      return false;
  }
  if (!a.terminal_points.positions.empty()) return same_points(a.terminal_points, b.terminal_points, tolerance);
  if (a.terminal.triangles.empty()) return true;
  return same_surface(a.terminal, b.terminal, tolerance);
}

}  // namespace dg
