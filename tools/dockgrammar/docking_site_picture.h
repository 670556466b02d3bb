#pragma once
// Picture of the docking sites `analyze` found: where each operation cuts the exemplar.

#include "geometry/prepared_model.h"
#include "grammar/docking_sites.h"

#include <filesystem>
#include <string>

namespace dg::cli {

/// Writes `png` and `ply` (same picture as a coloured mesh): the exemplar cut into voxel cells,
/// light grey, with every docker D filled in its operation's colour (insert green, delete red,
/// replace blue; slippable sites grey, they make no rule) and its docking site, the band cells
/// touching D, in a dark shade of that colour, so the sites read as curves around the dockers.
/// Larger dockers are painted first, so nested sites stay visible; a docker covering more than
/// half of the model is only outlined (filled, it would hide all the others). `up_axis` as for
/// picture_options. A point cloud is drawn as splats, each point in its cell's colour, and `ply`
/// is the coloured cloud. Writes nothing and returns false when there is no docking site.
bool write_docking_site_picture(const std::filesystem::path& png, const std::filesystem::path& ply,
                                const PreparedModel& prepared, const DockingSiteResult& docking,
                                const std::string& up_axis);

}  // namespace dg::cli
