#pragma once
// Picture helpers shared by the subcommands that draw models.

#include "geometry/image.h"
#include "geometry/mesh.h"
#include "geometry/render_mesh.h"

#include <cstddef>

namespace dg::cli {

/// Render options with the up axis guessed from the model: z when the model is thinnest along
/// y (facades, fences lying in the x-z plane), y otherwise (the common OBJ/glTF convention).
MeshRenderOptions picture_options(const TriangleMesh& mesh);

/// A distinct, readable colour for class i (cycled).
Rgba8 class_color(std::size_t i);

}  // namespace dg::cli
