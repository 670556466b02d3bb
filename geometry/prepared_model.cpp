#include "geometry/prepared_model.h"

#include "geometry/errors.h"
#include "geometry/material_classes.h"
#include "geometry/model_io.h"
#include "geometry/stopwatch.h"
#include "geometry/submesh.h"
#include "geometry/t_junctions.h"

#include <cmath>

namespace dg {
namespace {

// Distance from an edge, relative to the bounding-box diagonal, within which a vertex splits it.
constexpr double kTJunctionTolerance = 1e-9;

void check_option(double value, const char* name) {
  if (!std::isfinite(value) || value < 0.0)
    throw InputError(std::string(name) + " must be a positive number of model units (0 or absent = default)");
}

// The voxel size prepare_model builds the surface with.
double voxel_size(const BoundingBox& bounds, const PrepareOptions& options) {
  if (options.eps > 0.0) return options.eps;
  return (options.r > 0.0 ? options.r : default_radius(bounds)) / 4.0;
}

// Moves `model` by -origin where it lies beyond the voxel grid's reach; returns the origin.
Vec3 move_near_origin(Model& model, const PrepareOptions& options) {
  const BoundingBox bounds = model.bounds();
  const Vec3 origin = far_model_origin(bounds, voxel_size(bounds, options));
  if (origin.isZero()) return origin;
  RigidTransform to_local;
  to_local.translation = -origin;
  if (model.is_point_cloud())
    model.cloud = transformed(model.cloud, to_local);
  else
    model.mesh = transformed(model.mesh, to_local);
  return origin;
}

}  // namespace

Vec3 far_model_origin(const BoundingBox& bounds, double eps) {
  if (bounds.empty() || !(eps > 0.0) || within_voxel_reach(bounds, eps)) return Vec3::Zero();
  const double side = bounds.longest_side();
  const double step = side > 0.0 ? std::pow(10.0, std::ceil(std::log10(side))) : 1.0;
  const Vec3 middle = 0.5 * (bounds.min + bounds.max);
  return (middle / step).array().round().matrix() * step;
}

PreparedModel prepare_model(const std::filesystem::path& path, const PrepareOptions& options,
                            const ProgressCallback& progress) {
  check_option(options.r, "-r");
  check_option(options.eps, "--voxel");
  Stopwatch clock;
  report_progress(progress, "load", 0.0);
  Model model = read_model(path);
  const double load_seconds = clock.lap();
  PreparedModel prepared = prepare_model(std::move(model), options, progress);
  prepared.timings.insert(prepared.timings.begin(), {"load", load_seconds});
  return prepared;
}

PreparedModel prepare_model(Model model, const PrepareOptions& options, const ProgressCallback& progress) {
  check_option(options.r, "-r");
  check_option(options.eps, "--voxel");
  PreparedModel prepared;
  Stopwatch clock;
  const std::string name = model.source_path.empty() ? std::string("model") : model.source_path;
  const bool matching_materials = options.match_materials || !options.same_materials.empty();
  VoxelSurfaceOptions voxel_options;
  voxel_options.r = options.r;
  voxel_options.eps = options.eps;
  voxel_options.corner_angle_degrees = options.corner_angle_degrees;
  try {
    // Groups are checked against the model's materials even when it has none (a clear error).
    if (matching_materials && (model.mesh.has_materials() || !options.same_materials.empty()))
      voxel_options.material_classes = material_classes(model.materials, options.same_materials);
    if (model.is_point_cloud()) {
      prepared.cleaning = clean_point_cloud(model.cloud);
      prepared.origin = move_near_origin(model, options);
      prepared.timings.push_back({"clean", clock.lap()});
      prepared.surface = build_voxel_surface(model.cloud, voxel_options, progress);
      prepared.cloud_sampling = point_statistics(model.cloud, kCloudStatisticsRadius * prepared.surface.eps());
      prepared.timings.push_back({"voxel surface", clock.lap()});
    } else {
      prepared.cleaning = clean_mesh(model.mesh);
      if (model.mesh.triangles.empty()) throw InputError("no triangles left after dropping degenerate ones");
      prepared.origin = move_near_origin(model, options);
      // A fan edge that skips a vertex of the neighbouring face leaves a crack that exists only in
      // the topology; as an open edge it would become a feature line that breaks symmetries.
      if (prepared.cleaning.boundary_edges > 0)
        prepared.cleaning.t_junctions_split =
            resolve_t_junctions(model.mesh, kTJunctionTolerance * model.mesh.bounds().diagonal());
      prepared.timings.push_back({"clean", clock.lap()});
      report_progress(progress, "feature lines", 0.0);
      prepared.feature_edges =
          find_feature_edges(model.mesh, options.sharp_angle_degrees, voxel_options.material_classes);
      prepared.feature_lines = extract_feature_lines(model.mesh, prepared.feature_edges,
                                                     voxel_size(model.mesh.bounds(), options), options.corner_angle_degrees);
      prepared.timings.push_back({"feature lines", clock.lap()});
      prepared.surface = build_voxel_surface(model.mesh, prepared.feature_edges, voxel_options, progress);
      prepared.timings.push_back({"voxel surface", clock.lap()});
    }
  } catch (const InputError& e) {
    throw InputError(name + ": " + e.what());
  }
  prepared.material_classes = std::move(voxel_options.material_classes);
  prepared.model = std::move(model);
  return prepared;
}

}  // namespace dg
