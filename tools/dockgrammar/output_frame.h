#pragma once
// How a written model is turned in its file: glTF (.glb) defines +y as up, other formats keep
// the model's own axes.

#include "geometry/rigid_transform.h"

#include <filesystem>

namespace dg::cli {

/// The motion from the model's frame to that of the file `path`: for a .glb file the rotation
/// that turns the model's up axis `up` (unit length, as picture_options gives it) onto +y, so the
/// variants of a z-up exemplar stand upright in glTF viewers; the identity for other formats
/// and for a y-up model.
RigidTransform file_frame(const std::filesystem::path& path, const Vec3& up);

}  // namespace dg::cli
