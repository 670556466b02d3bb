#pragma once
// One call from a model file to everything the 3D stages start from: the cleaned model,
// its cleaning report, feature edges and lines, and the voxel surface, with stage timings.

#include "geometry/cleaning.h"
#include "geometry/cloud_statistics.h"
#include "geometry/feature_lines.h"
#include "geometry/mesh.h"
#include "geometry/progress.h"
#include "geometry/voxel_surface.h"

#include <filesystem>
#include <string>
#include <vector>

namespace dg {

/// Wall-clock time of one named stage, seconds.
struct StageTiming {
  std::string stage;
  double seconds = 0.0;
};

/// Sum of the seconds of `timings`.
inline double total_seconds(const std::vector<StageTiming>& timings) {
  double seconds = 0.0;
  for (const StageTiming& t : timings) seconds += t.seconds;
  return seconds;
}

/// Radius (in eps) of the neighbourhoods PreparedModel::cloud_sampling is measured in: about 40
/// points of a cloud with 3 points per occupied voxel.
inline constexpr double kCloudStatisticsRadius = 2.0;

struct PrepareOptions {
  double r = 0.0;    ///< similarity radius in model units; 0 = 1.6 % of the longest bounding-box side
  double eps = 0.0;  ///< voxel size in model units; 0 = r / 4
  double sharp_angle_degrees = kDefaultSharpAngleDegrees;    ///< dihedral angle of feature edges
  double corner_angle_degrees = kDefaultCornerAngleDegrees;  ///< turning angle that splits feature lines
  /// Symmetries must also map materials onto the same materials, and material borders are feature
  /// lines (for patterns drawn only in materials on flat walls). Off: geometry alone, as in paper 001.
  bool match_materials = false;
  /// Groups of materials that match one another, each a comma-separated list of names or '*'
  /// patterns (material_classes()), for tints that vary at random. Not empty: materials are
  /// matched as with match_materials.
  std::vector<std::string> same_materials;
};

struct PreparedModel {
  Model model;  ///< welded and cleaned, moved by -origin
  /// Where the model file's coordinates put the model's own origin: every stage sees the file's
  /// coordinates minus this. Zero unless the model lies so far from the file's origin that the
  /// voxel grid could not reach it (a building in survey coordinates); then a round point near
  /// the middle of its bounding box.
  Vec3 origin = Vec3::Zero();
  CleaningReport cleaning;
  std::vector<FeatureEdge> feature_edges;  ///< empty for point clouds
  FeatureLines feature_lines;              ///< empty for point clouds
  VoxelSurface surface;
  /// Point clouds: how far apart the points lie and how far they scatter off the surface, from
  /// their neighbours within kCloudStatisticsRadius eps (noise_wide: twice that;
  /// point_statistics); zeros for meshes.
  PointStatistics cloud_sampling;
  /// Empty when materials are not matched; else the matching class of each material
  /// (material_classes()), as the voxel surface and the feature edges used them.
  std::vector<std::uint32_t> material_classes;
  std::vector<StageTiming> timings;  ///< load, clean, feature lines, voxel surface

  /// The surface keeps materials apart and material borders are feature edges
  /// (PrepareOptions::match_materials or same_materials on a mesh with materials).
  bool materials_matched() const { return !material_classes.empty() && model.mesh.has_materials(); }
};

/// Loads, cleans (then splits open edges at T-junction vertices within 1e-9 of the bounding-box
/// diagonal), moves the model near the origin when it lies beyond the voxel grid's reach (see
/// PreparedModel::origin), finds feature lines and builds the voxel surface of a model file.
/// Throws InputError for unreadable/invalid files and impossible options (negative, NaN r).
PreparedModel prepare_model(const std::filesystem::path& path, const PrepareOptions& options = {},
                            const ProgressCallback& progress = {});

/// The same for a model already in memory (source_path is used in messages only).
PreparedModel prepare_model(Model model, const PrepareOptions& options = {}, const ProgressCallback& progress = {});

/// Zero when the voxel grid of size `eps` reaches all of `bounds`; else the point the model is
/// moved to the origin from: the middle of the box rounded to a multiple of the smallest power
/// of ten at least its longest side (10,000,020.5 ... 10,000,031.5 gives 10,000,000).
Vec3 far_model_origin(const BoundingBox& bounds, double eps);

}  // namespace dg
