#include "symmetry/symmetry_detection.h"

#include "symmetry/cloud_icp.h"
#include "symmetry/cloud_keypoints.h"
#include "symmetry/pinned_area.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <cmath>
#include <numbers>

namespace dg {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

SymmetryResult detect_symmetries(const PreparedModel& prepared, const SymmetryOptions& options,
                                 const ProgressCallback& progress) {
  SymmetryResult result;
  result.region = options.region;
  const VoxelSurface& surface = prepared.surface;
  const double eps = surface.eps();
  const Vec3 centre = 0.5 * (prepared.model.bounds().min + prepared.model.bounds().max);

  auto start = std::chrono::steady_clock::now();
  report_progress(progress, "symmetry candidates", 0.0);
  std::vector<Keypoint> keypoints = prepared.model.is_point_cloud()
                                        ? cloud_keypoints(prepared.model.cloud, surface)
                                        : feature_keypoints(prepared.feature_lines);
  // Feature lines that are all closed loops (the rings of a chain's links) have no ends: their
  // vertices align instead.
  const bool loops_only = keypoints.empty() && !prepared.model.is_point_cloud();
  if (loops_only) keypoints = loop_keypoints(prepared.feature_lines, prepared.model.mesh);
  if (keypoints.size() > options.max_keypoints) {  // evenly thinned: voting and ICP scale with their number
    std::vector<Keypoint> thinned;
    for (std::size_t i = 0; i < options.max_keypoints; ++i) thinned.push_back(keypoints[i * keypoints.size() / options.max_keypoints]);
    keypoints = std::move(thinned);
  }
  CandidateOptions candidate_options = options.candidates;
  candidate_options.eps = eps;
  if (prepared.model.is_point_cloud()) {
    candidate_options.snap_to_translation_radians = options.cloud_snap_to_translation_degrees * std::numbers::pi / 180.0;
    candidate_options.match_radius_scale = options.cloud_match_radius_scale;
    candidate_options.dihedral_tolerance_degrees = options.cloud_dihedral_tolerance_degrees;
  }
  CandidateStats candidate_stats;
  std::vector<Candidate> candidates = find_candidates(keypoints, centre, candidate_options, &candidate_stats);
  // Cloud keypoints of one corner can lie a few voxels apart, proposing tiny motions that
  // slide flat walls along themselves; densely sampled walls match under any such slide. Only
  // motions that move some corner of the bounding box by more than 2 r are kept.
  const BoundingBox box = prepared.model.bounds();
  auto barely_moves = [&](const Candidate& c) { return largest_corner_move(c.transform, box) <= 2.0 * surface.r(); };
  if (prepared.model.is_point_cloud()) std::erase_if(candidates, barely_moves);
  result.stats.keypoints = candidate_stats.keypoints;
  result.stats.pair_transforms = candidate_stats.pair_transforms;
  result.stats.candidates = candidates.size();
  result.timings.push_back({"candidates", seconds_since(start)});
  if (candidates.empty()) {
    result.note = prepared.model.is_point_cloud()
                      ? (keypoints.empty() ? "no candidates: the point cloud has no creases or corners to align"
                                           : "no candidates: no two creases of the point cloud match under a rigid motion")
                      : (keypoints.empty() ? "no candidates: the model has no feature lines (smooth or organic surface)"
                         : loops_only ? "no candidates: its feature lines are closed loops, and no two of their vertices match under a rigid motion"
                                      : "no candidates: no two feature-line ends match under a rigid motion");
    return result;
  }
  if (candidates.size() > options.max_verified) {
    result.stats.unverified = candidates.size() - options.max_verified;
    candidates.resize(options.max_verified);
  }
  // Point-to-plane ICP on the cloud's points; the refined motion in canonical form, its keypoint
  // matches swapped when that form is the inverse.
  auto refine_cloud_candidate = [&](Candidate& c) {
    const RigidTransform refined = refine_on_points(prepared.model.cloud, surface, c.transform);
    c.transform = canonical_motion(refined, 0.5 * eps);
    if (c.transform.translation != refined.translation)
      for (auto& [from, to] : c.matches) std::swap(from, to);
  };
  if (prepared.model.is_point_cloud()) {
    // A few corner keypoints leave a pitch uncertain by a fraction of a voxel: refit on all points.
    tbb::parallel_for(std::size_t(0), candidates.size(), [&](std::size_t i) { refine_cloud_candidate(candidates[i]); });
    std::erase_if(candidates, barely_moves);  // refined onto such a slide, or the identity
    std::vector<Candidate> distinct;
    for (Candidate& c : candidates) {
      const bool known = std::any_of(distinct.begin(), distinct.end(),
                                     [&](const Candidate& d) { return same_motion(d.transform, c.transform, centre, 0.5 * eps); });
      if (!known) distinct.push_back(std::move(c));
    }
    candidates = std::move(distinct);
  }

  start = std::chrono::steady_clock::now();
  report_progress(progress, "symmetric regions", 0.3);
  const CellMatcher matcher(surface, prepared.model.is_point_cloud() ? &prepared.model.cloud : nullptr, options.region);
  const std::optional<SurfaceParts> parts =
      prepared.model.is_point_cloud() ? std::nullopt : std::optional<SurfaceParts>(surface_parts(surface));
  const double total = surface.total_area();
  const double area_scale = prepared.model.is_point_cloud() || total <= 0.0 ? 1.0 : prepared.model.mesh.area() / total;
  // Verifies one candidate; an empty optional when it is rejected (counted in `stats`).
  auto evaluate = [&](const Candidate& candidate, SymmetryStats& stats) -> std::optional<DetectedSymmetry> {
    std::vector<std::uint32_t> seeds;
    const auto& matches = candidate.matches;
    const std::size_t stride = std::max<std::size_t>(1, matches.size() / options.max_seeds);
    for (std::size_t m = 0; m < matches.size(); m += stride) {
      const std::int64_t cell = surface.find(surface.voxel_of(keypoints[matches[m].first].position));
      if (cell < 0) continue;
      seeds.push_back(static_cast<std::uint32_t>(cell));
      // A noisy cloud's corner cells rarely match (their planes are fitted to few points each):
      // the flat cells around them seed too.
      if (prepared.model.is_point_cloud())
        for (std::uint32_t n : surface.neighbours(static_cast<std::uint32_t>(cell))) seeds.push_back(n);
    }
    std::sort(seeds.begin(), seeds.end());
    seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
    SymmetricRegion region = symmetric_region(matcher, surface, candidate.transform, seeds, prepared.model.is_point_cloud(),
                                              parts ? &*parts : nullptr);
    ++stats.verified;
    if (region.rejected_early) {
      ++stats.rejected_early;
      return std::nullopt;
    }
    const double fraction = total > 0.0 ? region.r_symmetric_area / total : 0.0;
    if (fraction < options.min_r_symmetric_fraction) {
      ++stats.rejected_small;
      return std::nullopt;
    }
    DetectedSymmetry symmetry;
    symmetry.transform = candidate.transform;
    symmetry.kind = motion_kind(symmetry.transform, 0.5 * std::numbers::pi / 180.0, 0.5 * eps);
    symmetry.screw = screw_parameters(symmetry.transform);
    symmetry.support = candidate.matches.size();
    symmetry.symmetric_fraction = region.symmetric_area / total;
    symmetry.r_symmetric_fraction = fraction;
    symmetry.symmetric_area = region.symmetric_area * area_scale;
    symmetry.r_symmetric_area = region.r_symmetric_area * area_scale;
    symmetry.pinned_fraction = pinned_area(matcher, surface, candidate.transform, region.r_symmetric_cells, 0.5 * surface.r()) / total;
    symmetry.region = std::move(region);
    return symmetry;
  };

  std::vector<std::optional<DetectedSymmetry>> evaluated(candidates.size());
  std::vector<SymmetryStats> candidate_stats_each(candidates.size());
  tbb::parallel_for(std::size_t(0), candidates.size(),
                    [&](std::size_t i) { evaluated[i] = evaluate(candidates[i], candidate_stats_each[i]); });
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    result.stats.verified += candidate_stats_each[i].verified;
    result.stats.rejected_early += candidate_stats_each[i].rejected_early;
    result.stats.rejected_small += candidate_stats_each[i].rejected_small;
    if (evaluated[i]) result.symmetries.push_back(std::move(*evaluated[i]));
  }

  // Repetition families: probe the powers of each small motion that voting did not propose.
  const std::size_t proposed = result.symmetries.size();
  for (std::size_t g = 0; g < proposed; ++g) {
    const RigidTransform generator = result.symmetries[g].transform;
    RigidTransform power = generator;
    for (int k = 2; k <= options.max_power; ++k) {
      power = generator.after(power);
      if (same_motion(power, RigidTransform{}, centre, eps)) break;  // back to the identity
      const RigidTransform canonical = canonical_motion(power, 0.5 * eps);
      auto listed_near = [&](const RigidTransform& motion) {
        return std::find_if(result.symmetries.begin(), result.symmetries.end(),
                            [&](const DetectedSymmetry& s) { return same_motion(s.transform, motion, centre, eps); });
      };
      const auto known = listed_near(canonical);
      // A listed motion within eps of the power that only slides may have drifted along a wall
      // off the power (the Quaternius bank's 109.26 for 2 x 53.99: its columns do not match).
      const bool drifted_slide = known != result.symmetries.end() && known->pinned_fraction < options.min_r_symmetric_fraction &&
                                 !same_motion(known->transform, canonical, centre, 0.25 * eps);
      if (known != result.symmetries.end() && !drifted_slide) continue;
      Candidate probe = refine_candidate(canonical, keypoints, candidate_options);
      if (prepared.model.is_point_cloud()) {
        refine_cloud_candidate(probe);
        if (barely_moves(probe)) continue;  // refined onto a slide or the identity
      }
      if (probe.matches.size() < candidate_options.min_support) break;
      // Refinement on keypoints can drift the same way: then the exact power competes.
      const bool drifted = !prepared.model.is_point_cloud() && !same_motion(probe.transform, canonical, centre, 0.25 * eps);
      const bool refined_listed = listed_near(probe.transform) != result.symmetries.end();  // ICP settled on a listed motion
      if (refined_listed && !drifted && !drifted_slide) continue;
      std::optional<DetectedSymmetry> found = evaluate(probe, result.stats);
      if (drifted) {
        Candidate exact = probe;
        exact.transform = canonical;
        std::optional<DetectedSymmetry> exact_found = evaluate(exact, result.stats);
        if (exact_found && (!found || exact_found->r_symmetric_area > found->r_symmetric_area)) found = std::move(exact_found);
      }
      if (drifted_slide) {
        if (found && found->pinned_fraction >= options.min_r_symmetric_fraction) *known = std::move(*found);
        continue;
      }
      if (!found) {
        if (refined_listed) continue;
        break;
      }
      if (listed_near(found->transform) != result.symmetries.end()) continue;
      result.symmetries.push_back(std::move(*found));
    }
  }
  const double region_seconds = seconds_since(start);
  result.timings.push_back({"symmetric regions", region_seconds});
  result.stats.seconds_per_verified = region_seconds / static_cast<double>(std::max<std::size_t>(1, result.stats.verified));
  std::stable_sort(result.symmetries.begin(), result.symmetries.end(),
                   [](const DetectedSymmetry& a, const DetectedSymmetry& b) { return a.r_symmetric_area > b.r_symmetric_area; });

  start = std::chrono::steady_clock::now();
  std::vector<RigidTransform> motions;
  std::vector<std::string> kinds;
  std::vector<char> repeats;
  for (const DetectedSymmetry& s : result.symmetries) {
    motions.push_back(s.transform);
    kinds.push_back(s.kind);
    repeats.push_back(s.pinned_fraction >= options.min_r_symmetric_fraction ? 1 : 0);
  }
  result.families = group_families(motions, kinds, repeats, centre, eps);
  for (std::size_t f = 0; f < result.families.size(); ++f)
    for (std::size_t m = 0; m < result.families[f].members.size(); ++m) {
      result.symmetries[result.families[f].members[m]].family = f;
      result.symmetries[result.families[f].members[m]].power = result.families[f].powers[m];
    }
  result.timings.push_back({"families", seconds_since(start)});
  if (result.symmetries.empty()) result.note = "no candidate had enough r-symmetric area";
  report_progress(progress, "symmetry", 1.0);
  return result;
}

}  // namespace dg
