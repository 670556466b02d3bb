#pragma once
// A picture of a grown scene: guide outlines (thin, grey), link start edges (thin, blue) and
// the grown elements (black segments, green motifs), as a Drawing for render.h.

#include "synthesis/drawing.h"
#include "synthesis/growth.h"
#include "synthesis/growth_scene.h"

namespace dg {

/// The drawing of `result` over the guides of `scene` (y-up drawing units).
Drawing growth_drawing(const GrowthScene& scene, const GrowthResult& result);

}  // namespace dg
