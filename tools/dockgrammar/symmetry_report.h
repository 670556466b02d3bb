#pragma once
// Text and JSON reports of detected symmetries, and their coloured pictures.

#include "geometry/prepared_model.h"
#include "symmetry/symmetry_detection.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace dg::cli {

/// "t = (x, y, z), |t| = ..." for a translation; angle (degrees), axis and axis point for a
/// rotation, plus the rise along the axis for a screw (`kind` as in DetectedSymmetry). Lengths
/// within 1e-6 `eps` (the voxel size, model units) of 0 print as 0.
std::string describe_motion(const RigidTransform& t, const std::string& kind, double eps);

/// A rigid motion as a 4x4 row-major matrix (rows of four numbers), model units.
nlohmann::json matrix_json(const RigidTransform& t);

/// Readable table of the first `top` symmetries (kind, motion, areas, family), motions in the
/// model file's coordinates (PreparedModel::origin), lengths as describe_motion prints them.
std::string symmetry_table(const SymmetryResult& result, std::size_t top, const PreparedModel& prepared);

/// One sentence saying how many candidates went unverified and that --candidates verifies more
/// (ends with a newline); empty when every candidate was verified.
std::string unverified_candidates_text(const SymmetryResult& result);

/// {"symmetries": [...], "families": [...], "stats": {...}, "timings_s": {...}} for the first
/// `top`, motions in the model file's coordinates (`origin`: PreparedModel::origin).
nlohmann::json symmetry_json(const SymmetryResult& result, std::size_t top, const Vec3& origin);

/// Writes DIR/symmetry_NN.ply (vertex colours) and DIR/symmetry_NN.png for the first `top`
/// symmetries: r-symmetric area red, symmetric but within r of its border pink, the image of
/// the r-symmetric area under T blue (violet where both), the rest grey; a point cloud's points
/// take their cell's colour (drawn as splats; the PLY is the coloured cloud). `up_axis` is "x",
/// "y", "z" or empty (guessed), as picture_options takes it.
void write_symmetry_pictures(const std::filesystem::path& folder, const PreparedModel& prepared,
                             const SymmetryResult& result, std::size_t top, const std::string& up_axis);

}  // namespace dg::cli
