#include "synthesis/verify.h"

#include "geometry/cleaning.h"
#include "geometry/cloud_cell_geometry.h"
#include "geometry/errors.h"
#include "geometry/feature_edges.h"
#include "geometry/feature_lines.h"
#include "geometry/model_io.h"
#include "geometry/prepared_model.h"
#include "geometry/self_intersections.h"
#include "geometry/stopwatch.h"
#include "geometry/submesh.h"
#include "geometry/voxel_surface.h"
#include "symmetry/cloud_keypoints.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace dg {
namespace {

// A welded, cleaned mesh with its cleaning report and feature lines.
struct CleanModel {
  TriangleMesh mesh;
  CleaningReport cleaning;
  FeatureLines feature_lines;
};

std::string name_of(const Model& model, const char* role) {
  return model.source_path.empty() ? std::string(role) : model.source_path;
}

CleanModel clean_model(Model model, const char* role) {
  const std::string name = name_of(model, role);
  CleanModel clean{std::move(model.mesh), {}, {}};
  clean.cleaning = clean_mesh(clean.mesh);
  if (clean.mesh.triangles.empty()) throw InputError(name + ": no triangles left after dropping degenerate ones");
  return clean;
}

void add_feature_lines(CleanModel& model, double r) {
  model.feature_lines = extract_feature_lines(model.mesh, find_feature_edges(model.mesh), r / 4.0);
}

ModelChecks topology_checks(const CleanModel& model) {
  ModelChecks checks;
  const CleaningReport& c = model.cleaning;
  checks.boundary_edges = c.boundary_edges;
  checks.non_manifold_edges = c.non_manifold_edges;
  checks.inconsistent_edges = c.inconsistent_edges;
  checks.closed = c.boundary_edges == 0 && c.non_manifold_edges == 0;
  checks.oriented = c.inconsistent_edges == 0;
  checks.triangles = c.triangles;
  return checks;
}

// A cleaned point cloud with unit normals (fitted when the file had none), its corners and its
// crease samples.
struct CleanCloud {
  PointCloud cloud;
  std::vector<Keypoint> keypoints, creases;
  bool normals_estimated = false;
};

CleanCloud clean_cloud(Model model, const char* role) {
  const std::string name = name_of(model, role);
  CleanCloud clean{std::move(model.cloud), {}, {}, false};
  clean_point_cloud(clean.cloud);
  if (clean.cloud.positions.empty()) throw InputError(name + ": the " + role + " has no points");
  return clean;
}

// The corners and crease samples of the cloud's voxel surface at eps = r / 4, and normals from
// its fitted cell planes where the file had none.
void add_normals_and_corners(CleanCloud& clean, double r) {
  VoxelSurfaceOptions voxel;
  voxel.r = r;
  voxel.eps = r / 4.0;
  const VoxelSurface surface = build_voxel_surface(clean.cloud, voxel);
  if (!clean.cloud.has_normals()) {
    clean.cloud.normals = cell_plane_normals(clean.cloud, surface);
    clean.normals_estimated = true;
  }
  clean.keypoints = cloud_keypoints(clean.cloud, surface);
  clean.creases = cloud_crease_samples(clean.cloud, surface);
}

ModelChecks cloud_checks(const CleanCloud& clean) {
  ModelChecks checks;
  checks.point_cloud = true;
  checks.points = clean.cloud.positions.size();
  checks.normals_estimated = clean.normals_estimated;
  return checks;
}

BoundingBox bounds_of(const CleanModel& model) { return model.mesh.bounds(); }
BoundingBox bounds_of(const CleanCloud& cloud) { return cloud.cloud.bounds(); }

SimilarityInput similarity_input(const CleanModel& model) {
  SimilarityInput input;
  input.mesh = &model.mesh;
  input.feature_lines = &model.feature_lines;
  return input;
}

SimilarityInput similarity_input(const CleanCloud& cloud) {
  SimilarityInput input;
  input.cloud = &cloud.cloud;
  input.cloud_keypoints = cloud.keypoints;
  input.cloud_creases = cloud.creases;
  return input;
}

// The start both kinds share: the report's paths, both sides cleaned by `clean` (stage "clean"),
// r (the option, else the default for the cleaned exemplar's bounds), then both sides given
// to `prepare` with r (stage `stage`).
template <class Clean, class Prepare>
auto prepare_sides(Model exemplar, Model candidate, const VerifyOptions& options, const ProgressCallback& progress,
                   VerifyReport& report, Clean clean, const char* stage, Prepare prepare) {
  report.exemplar_path = exemplar.source_path;
  report.candidate_path = candidate.source_path;
  Stopwatch clock;
  report_progress(progress, "clean", 0.0);
  auto exemplar_clean = clean(std::move(exemplar), "exemplar");
  auto candidate_clean = clean(std::move(candidate), "candidate");
  const double r = options.r > 0.0 ? options.r : default_radius(bounds_of(exemplar_clean));
  if (!(r > 0.0)) throw InputError(report.exemplar_path + ": the exemplar has zero extent; pass -r");
  report.timings.push_back({"clean", clock.lap()});
  report_progress(progress, stage, 0.0);
  prepare(exemplar_clean, r);
  prepare(candidate_clean, r);
  report.timings.push_back({stage, clock.lap()});
  return std::make_tuple(std::move(exemplar_clean), std::move(candidate_clean), r);
}

// Moves both models by the same amount when the exemplar lies beyond the voxel grid's reach
// (far_model_origin: a model in survey coordinates), as analyze does.
void move_both_near_origin(Model& exemplar, Model& candidate, const VerifyOptions& options) {
  const BoundingBox bounds = exemplar.bounds();
  const double r = options.r > 0.0 ? options.r : default_radius(bounds);
  RigidTransform to_local;
  to_local.translation = -far_model_origin(bounds, r / 4.0);
  if (to_local.translation.isZero()) return;
  for (Model* model : {&exemplar, &candidate}) {
    model->mesh = transformed(model->mesh, to_local);
    model->cloud = transformed(model->cloud, to_local);
  }
}

// The r-similarity check of both kinds: the estimated fraction against the option's minimum.
CheckResult r_similarity_check(const RSimilarityResult& similarity, const VerifyOptions& options) {
  return {"r_similarity", similarity.fraction >= options.min_similar_fraction,
          fmt::format("r-similar fraction >= {}", options.min_similar_fraction)};
}

// Two point clouds: only r-similarity applies (a cloud has no edges to be closed or faces to
// intersect).
VerifyReport verify_clouds(Model exemplar, Model candidate, const VerifyOptions& options, const ProgressCallback& progress) {
  VerifyReport report;
  auto [exemplar_clean, candidate_clean, r] = prepare_sides(std::move(exemplar), std::move(candidate), options, progress,
                                                             report, clean_cloud, "normals and corners", add_normals_and_corners);
  Stopwatch clock;
  report.exemplar = cloud_checks(exemplar_clean);
  report.candidate = cloud_checks(candidate_clean);
  report.similarity = estimate_r_similarity(similarity_input(exemplar_clean), similarity_input(candidate_clean), r,
                                            options.similarity, progress);
  report.timings.push_back({"r-similarity", clock.lap()});
  report.checks.push_back(r_similarity_check(report.similarity, options));
  report.pass = report.checks.back().pass;
  return report;
}

}  // namespace

VerifyReport verify_models(const std::filesystem::path& exemplar, const std::filesystem::path& candidate,
                           const VerifyOptions& options, const ProgressCallback& progress) {
  Stopwatch clock;
  report_progress(progress, "load", 0.0);
  Model exemplar_model = read_model(exemplar);
  Model candidate_model = read_model(candidate);
  const double load_seconds = clock.lap();
  VerifyReport report = verify_models(std::move(exemplar_model), std::move(candidate_model), options, progress);
  report.timings.insert(report.timings.begin(), {"load", load_seconds});
  return report;
}

VerifyReport verify_models(Model exemplar, Model candidate, const VerifyOptions& options,
                           const ProgressCallback& progress) {
  if (!std::isfinite(options.r) || options.r < 0.0)
    throw InputError("-r must be a positive number of model units (0 or absent = default)");
  if (exemplar.is_point_cloud() != candidate.is_point_cloud()) {
    const bool cloud_first = exemplar.is_point_cloud();
    throw InputError(fmt::format("{} is a point cloud and {} a mesh: verify compares two meshes or two point clouds",
                                 name_of(cloud_first ? exemplar : candidate, cloud_first ? "the exemplar" : "the candidate"),
                                 name_of(cloud_first ? candidate : exemplar, cloud_first ? "the candidate" : "the exemplar")));
  }
  move_both_near_origin(exemplar, candidate, options);
  if (exemplar.is_point_cloud()) return verify_clouds(std::move(exemplar), std::move(candidate), options, progress);
  VerifyReport report;
  auto [exemplar_clean, candidate_clean, r] = prepare_sides(std::move(exemplar), std::move(candidate), options, progress,
                                                             report, clean_model, "feature lines", add_feature_lines);
  Stopwatch clock;

  report.exemplar = topology_checks(exemplar_clean);
  report.candidate = topology_checks(candidate_clean);
  report_progress(progress, "self-intersections", 0.0);
  const SelfIntersections exemplar_intersections =
      find_self_intersections(exemplar_clean.mesh, SelfIntersectionOptions{0});
  const SelfIntersections candidate_intersections =
      find_self_intersections(candidate_clean.mesh, SelfIntersectionOptions{options.max_intersecting_pairs});
  report.exemplar.self_intersects = exemplar_intersections.any;
  report.candidate.self_intersects = candidate_intersections.any;
  report.candidate.self_intersections = candidate_intersections.pairs.size();
  report.candidate.self_intersections_capped = candidate_intersections.capped;
  report.timings.push_back({"self-intersections", clock.lap()});

  report.similarity = estimate_r_similarity(similarity_input(exemplar_clean), similarity_input(candidate_clean), r,
                                            options.similarity, progress);
  report.timings.push_back({"r-similarity", clock.lap()});

  const bool exemplar_closed = report.exemplar.closed && report.exemplar.oriented;
  report.checks.push_back({"closed", !exemplar_closed || (report.candidate.closed && report.candidate.oriented),
                           exemplar_closed ? "closed and oriented (the exemplar is)"
                                           : "nothing (the exemplar is not closed and oriented)"});
  report.checks.push_back({"self_intersections", exemplar_intersections.any || !candidate_intersections.any,
                           exemplar_intersections.any ? "nothing (the exemplar self-intersects)"
                                                      : "no intersecting triangle pairs (the exemplar has none)"});
  report.checks.push_back(r_similarity_check(report.similarity, options));
  report.pass = std::all_of(report.checks.begin(), report.checks.end(), [](const CheckResult& c) { return c.pass; });
  return report;
}

namespace {

// Topology fields of one side (point clouds: their point count).
nlohmann::json checks_json(const ModelChecks& c) {
  if (c.point_cloud) return {{"point_cloud", true}, {"points", c.points}, {"normals_estimated", c.normals_estimated}};
  return {{"closed", c.closed},
          {"oriented", c.oriented},
          {"boundary_edges", c.boundary_edges},
          {"non_manifold_edges", c.non_manifold_edges},
          {"inconsistent_edges", c.inconsistent_edges},
          {"triangles", c.triangles}};
}

}  // namespace

nlohmann::json to_json(const VerifyReport& report) {
  const ModelChecks& c = report.candidate;
  const RSimilarityResult& s = report.similarity;
  nlohmann::json out = {{"exemplar_path", report.exemplar_path}, {"candidate_path", report.candidate_path}};
  out.update(checks_json(c));
  if (!c.point_cloud) {
    out["self_intersections"] = c.self_intersections;
    out["self_intersections_capped"] = c.self_intersections_capped;
  }
  out.update(nlohmann::json{{"r", s.r},
                            {"tolerance", s.tolerance},
                            {"samples", s.samples},
                            {"r_similar_samples", s.similar},
                            {"r_similar_fraction", s.fraction},
                            {"pass", report.pass}});
  const ModelChecks& e = report.exemplar;
  out["exemplar"] = checks_json(e);
  if (!e.point_cloud) {
    out["exemplar"]["self_intersects"] = e.self_intersects;
  }
  out["similarity"] = {{"motions", s.motions},
                       {"searched_samples", s.searched},
                       {"dense_samples_exemplar", s.dense_samples_exemplar},
                       {"dense_samples_candidate", s.dense_samples_candidate}};
  nlohmann::json dissimilar = nlohmann::json::array();
  for (std::size_t i = 0; i < std::min<std::size_t>(20, s.dissimilar_points.size()); ++i) {
    const Vec3& p = s.dissimilar_points[i];
    dissimilar.push_back({p.x(), p.y(), p.z()});
  }
  out["similarity"]["dissimilar_points_first_20"] = dissimilar;
  out["checks"] = nlohmann::json::object();
  for (const CheckResult& check : report.checks)
    out["checks"][check.name] = {{"pass", check.pass}, {"requirement", check.requirement}};
  out["timings_s"] = nlohmann::json::object();
  for (const StageTiming& t : report.timings) out["timings_s"][t.stage] = t.seconds;
  return out;
}

std::string to_text(const VerifyReport& report) {
  const ModelChecks& c = report.candidate;
  const RSimilarityResult& s = report.similarity;
  std::string text = fmt::format("verify {} against {} (r = {:.6g}, tolerance = {:.3g})\n", report.candidate_path,
                                 report.exemplar_path, s.r, s.tolerance);
  for (const CheckResult& check : report.checks) {
    std::string detail;
    if (check.name == "closed")
      detail = fmt::format("{} boundary, {} non-manifold, {} inconsistent edges", c.boundary_edges,
                           c.non_manifold_edges, c.inconsistent_edges);
    else if (check.name == "self_intersections")
      detail = fmt::format("{}{} intersecting triangle pairs", c.self_intersections_capped ? ">= " : "",
                           c.self_intersections);
    else
      detail = fmt::format("{} of {} samples r-similar ({:.4f})", s.similar, s.samples, s.fraction);
    text += fmt::format("  {} {:<19} {}; requires {}\n", check.pass ? "PASS" : "FAIL", check.name, detail,
                        check.requirement);
  }
  if (c.point_cloud)
    text += fmt::format("  point clouds ({} and {} points{}): closedness and self-intersections do not apply\n",
                        report.exemplar.points, c.points,
                        report.exemplar.normals_estimated || c.normals_estimated ? ", normals fitted to the points" : "");
  text += fmt::format("{}\n", report.pass ? "PASS" : "FAIL");
  return text;
}

}  // namespace dg
