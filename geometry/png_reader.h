#pragma once
// Reading PNG files (any bit depth, colour type and interlacing libpng reads) into an RGBA image.

#include "geometry/image.h"

#include <filesystem>

namespace dg {

/// The PNG file as 8-bit RGBA, top row first. Throws InputError "path: problem" when the file
/// cannot be read, is not a PNG, or is larger than 2^28 pixels.
Image read_png(const std::filesystem::path& path);

}  // namespace dg
