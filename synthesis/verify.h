#pragma once
// `verify`: an independent check of a generated model against its exemplar, without any
// grammar: closedness and manifoldness, self-intersections, and r-similarity (point clouds:
// r-similarity only).

#include "geometry/prepared_model.h"
#include "geometry/progress.h"
#include "synthesis/r_similarity.h"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace dg {

struct VerifyOptions {
  double r = 0.0;  ///< similarity radius, model units; 0 = default_radius of the exemplar's bounds
  RSimilarityOptions similarity;
  /// The r-similarity check passes when at least this fraction of test points match. A valid
  /// variant gives 1.0; 0.995 leaves room for 5 unlucky points in 1000 and still fails one
  /// wrong window in a 3 x 4 facade.
  double min_similar_fraction = 0.995;
  std::size_t max_intersecting_pairs = 1000;  ///< self-intersection enumeration stops here
};

/// Topology and self-intersections of one (welded, cleaned) model; a point cloud has only its
/// point count.
struct ModelChecks {
  bool point_cloud = false;
  std::size_t points = 0;          ///< point clouds: points after cleaning
  bool normals_estimated = false;  ///< point clouds: the file had no normals, they were fitted
  bool closed = false;    ///< no boundary and no non-manifold edges
  bool oriented = false;  ///< no two triangles traverse a shared edge the same way
  std::size_t boundary_edges = 0;
  std::size_t non_manifold_edges = 0;
  std::size_t inconsistent_edges = 0;
  std::size_t triangles = 0;
  bool self_intersects = false;
  std::size_t self_intersections = 0;  ///< intersecting triangle pairs found, at most the cap (exemplar: not counted)
  bool self_intersections_capped = false;
};

/// One named check: whether it passed and what it asked for.
struct CheckResult {
  std::string name;  ///< "closed", "self_intersections", "r_similarity"
  bool pass = false;
  std::string requirement;  ///< one line, e.g. "closed and oriented (the exemplar is)"
};

struct VerifyReport {
  std::string exemplar_path, candidate_path;
  ModelChecks exemplar, candidate;
  RSimilarityResult similarity;
  std::vector<CheckResult> checks;
  bool pass = false;
  std::vector<StageTiming> timings;  ///< seconds per stage
};

/// Loads and welds both models (InputError when unreadable or invalid, or when one is a point
/// cloud and the other a mesh), then checks the candidate: closed and oriented if the exemplar
/// is; free of self-intersections if the exemplar is; r-similar fraction at least
/// min_similar_fraction. Two point clouds get the r-similarity check only (normals fitted to
/// the points when a file has none).
VerifyReport verify_models(const std::filesystem::path& exemplar, const std::filesystem::path& candidate,
                           const VerifyOptions& options = {}, const ProgressCallback& progress = {});

/// The same for models already in memory.
VerifyReport verify_models(Model exemplar, Model candidate, const VerifyOptions& options = {},
                           const ProgressCallback& progress = {});

/// The report as JSON: closed, oriented, boundary_edges, non_manifold_edges, self_intersections
/// (point clouds instead: point_cloud, points, normals_estimated), r, samples,
/// r_similar_fraction, pass, checks {name: {pass, requirement}}, exemplar {...}, similarity
/// details and timings_s.
nlohmann::json to_json(const VerifyReport& report);

/// A short readable list with PASS/FAIL per check.
std::string to_text(const VerifyReport& report);

}  // namespace dg
