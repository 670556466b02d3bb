#pragma once
// Whether the units of a grid direction repeat anything, or only slide along themselves: a
// corridor, rail or wall extruded along the direction matches itself under every shift, so
// cutting it at any pitch gives "units" that are no repeated element.

#include "geometry/mesh.h"
#include "grammar/grid_rules.h"

namespace dg {

/// True when the repeated unit of `direction` (the surface of `mesh`, a triangle mesh, between
/// its planes head_units and head_units + 1) is invariant under every fraction of its motion:
/// the motion's velocity field (a translation's direction; a screw's rotation about its axis plus
/// slide) is tangent to the surface, within 1 degree, on all but 1e-3 of the unit's area, and
/// parallel to every open edge and every border between materials there. Such a unit is an
/// extrusion (of a corridor, rail or wall), not an element that repeats at the pitch: a stair
/// step, a baluster or a window frame faces along the motion somewhere, and a window painted on
/// a flat wall has borders across it. A screw's unit also slides when its slide alone (along the
/// axis) is tangent so: a faceted column that the screw's turn maps onto itself.
bool unit_only_slides(const TriangleMesh& mesh, const GridDirection& direction);

}  // namespace dg
