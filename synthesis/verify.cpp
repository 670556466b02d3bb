#include "synthesis/verify.h"

#include "geometry/cleaning.h"
#include "geometry/errors.h"
#include "geometry/feature_edges.h"
#include "geometry/feature_lines.h"
#include "geometry/model_io.h"
#include "geometry/self_intersections.h"
#include "geometry/stopwatch.h"
#include "geometry/voxel_surface.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace dg {
namespace {

// A welded, cleaned mesh with its cleaning report and feature lines.
struct CleanModel {
  TriangleMesh mesh;
  CleaningReport cleaning;
  FeatureLines feature_lines;
};

CleanModel clean_model(Model model, const char* role) {
  const std::string name = model.source_path.empty() ? std::string(role) : model.source_path;
  if (model.is_point_cloud()) throw InputError(name + ": the " + role + " is a point cloud; verify needs triangle meshes");
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
  VerifyReport report;
  report.exemplar_path = exemplar.source_path;
  report.candidate_path = candidate.source_path;
  Stopwatch clock;
  report_progress(progress, "clean", 0.0);
  CleanModel exemplar_clean = clean_model(std::move(exemplar), "exemplar");
  CleanModel candidate_clean = clean_model(std::move(candidate), "candidate");
  const double r = options.r > 0.0 ? options.r : default_radius(exemplar_clean.mesh.bounds());
  if (!(r > 0.0)) throw InputError(report.exemplar_path + ": the exemplar has zero extent; pass -r");
  report.timings.push_back({"clean", clock.lap()});
  report_progress(progress, "feature lines", 0.0);
  add_feature_lines(exemplar_clean, r);
  add_feature_lines(candidate_clean, r);
  report.timings.push_back({"feature lines", clock.lap()});

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

  report.similarity = estimate_r_similarity({exemplar_clean.mesh, exemplar_clean.feature_lines},
                                            {candidate_clean.mesh, candidate_clean.feature_lines}, r,
                                            options.similarity, progress);
  report.timings.push_back({"r-similarity", clock.lap()});

  const bool exemplar_closed = report.exemplar.closed && report.exemplar.oriented;
  report.checks.push_back({"closed", !exemplar_closed || (report.candidate.closed && report.candidate.oriented),
                           exemplar_closed ? "closed and oriented (the exemplar is)"
                                           : "none (the exemplar is not closed and oriented)"});
  report.checks.push_back({"self_intersections", exemplar_intersections.any || !candidate_intersections.any,
                           exemplar_intersections.any ? "none (the exemplar self-intersects)"
                                                      : "no intersecting triangle pairs (the exemplar has none)"});
  report.checks.push_back({"r_similarity", report.similarity.fraction >= options.min_similar_fraction,
                           fmt::format("r-similar fraction >= {}", options.min_similar_fraction)});
  report.pass = std::all_of(report.checks.begin(), report.checks.end(), [](const CheckResult& c) { return c.pass; });
  return report;
}

nlohmann::json to_json(const VerifyReport& report) {
  const ModelChecks& c = report.candidate;
  const RSimilarityResult& s = report.similarity;
  nlohmann::json out = {{"exemplar_path", report.exemplar_path},
                        {"candidate_path", report.candidate_path},
                        {"closed", c.closed},
                        {"oriented", c.oriented},
                        {"boundary_edges", c.boundary_edges},
                        {"non_manifold_edges", c.non_manifold_edges},
                        {"inconsistent_edges", c.inconsistent_edges},
                        {"triangles", c.triangles},
                        {"self_intersections", c.self_intersections},
                        {"self_intersections_capped", c.self_intersections_capped},
                        {"r", s.r},
                        {"tolerance", s.tolerance},
                        {"samples", s.samples},
                        {"r_similar_samples", s.similar},
                        {"r_similar_fraction", s.fraction},
                        {"pass", report.pass}};
  const ModelChecks& e = report.exemplar;
  out["exemplar"] = {{"closed", e.closed},
                     {"oriented", e.oriented},
                     {"boundary_edges", e.boundary_edges},
                     {"non_manifold_edges", e.non_manifold_edges},
                     {"triangles", e.triangles},
                     {"self_intersects", e.self_intersects}};
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
  text += fmt::format("{}\n", report.pass ? "PASS" : "FAIL");
  return text;
}

}  // namespace dg
