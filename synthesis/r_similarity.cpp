#include "synthesis/r_similarity.h"

#include "geometry/errors.h"
#include "geometry/cloud_statistics.h"
#include "geometry/surface_sampling.h"
#include "symmetry/candidates.h"
#include "synthesis/r_similarity_index.h"
#include "synthesis/r_similarity_match.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace dg {
namespace {

// A point with an orthonormal frame (tangent, normal, binormal) and what it may pair with.
struct Anchor {
  Vec3 position;
  Mat3 frame;  // columns: tangent, normal, binormal
  FeatureDescriptor descriptor;
};

Mat3 frame_of(const Vec3& tangent, const Vec3& normal, const Vec3& binormal) {
  Mat3 frame;
  frame << tangent, normal, binormal;
  return frame;
}

// Feature-line ends of a mesh, corners of a cloud.
std::vector<Anchor> keypoint_anchors(const SimilarityInput& input) {
  const std::vector<Keypoint> keypoints = input.feature_lines
                                              ? feature_keypoints(*input.feature_lines)
                                              : std::vector<Keypoint>(input.cloud_keypoints.begin(), input.cloud_keypoints.end());
  std::vector<Anchor> anchors;
  for (const Keypoint& k : keypoints) anchors.push_back({k.position, frame_of(k.tangent, k.normal, k.binormal), k.descriptor});
  return anchors;
}

// Feature samples (a cloud: crease samples) in both tangent directions.
std::vector<Anchor> sample_anchors(const SimilarityInput& input) {
  std::vector<Anchor> anchors;
  auto add = [&](const Vec3& position, const Vec3& tangent, const Vec3& normal, const Vec3& binormal,
                 const FeatureDescriptor& descriptor) {
    anchors.push_back({position, frame_of(tangent, normal, binormal), descriptor});
    anchors.push_back({position, frame_of(-tangent, normal, -binormal), descriptor});
  };
  if (input.feature_lines)
    for (const FeatureSample& s : input.feature_lines->samples) add(s.position, s.tangent, s.normal, s.binormal, s.descriptor);
  for (const Keypoint& k : input.cloud_creases) add(k.position, k.tangent, k.normal, k.binormal, k.descriptor);
  return anchors;
}

// Whole degrees of dihedral: the sort key of exemplar anchors.
double dihedral_key(const Anchor& a) { return std::round(a.descriptor.dihedral_degrees); }

// Sorts by whole degrees of dihedral, then in a fixed pseudo-random order (so a search budget
// is not spent on neighbouring samples of one line).
void sort_by_dihedral(std::vector<Anchor>& anchors) {
  std::vector<std::pair<std::pair<double, std::uint64_t>, std::size_t>> keys;
  for (std::size_t i = 0; i < anchors.size(); ++i) keys.push_back({{dihedral_key(anchors[i]), splitmix64(i)}, i});
  std::sort(keys.begin(), keys.end());
  std::vector<Anchor> sorted;
  sorted.reserve(anchors.size());
  for (const auto& key : keys) sorted.push_back(anchors[key.second]);
  anchors = std::move(sorted);
}

// The motion taking candidate anchor c onto exemplar anchor e, frame to frame.
RigidTransform align(const Anchor& c, const Anchor& e) {
  RigidTransform t;
  t.rotation = e.frame * c.frame.transpose();
  t.translation = e.position - t.rotation * c.position;
  return t;
}

struct Motion {
  RigidTransform transform;
  std::size_t hits = 0;
};

bool same_motion(const RigidTransform& a, const RigidTransform& b, double tolerance) {
  return (a.rotation - b.rotation).norm() < 1e-9 && (a.translation - b.translation).norm() < tolerance;
}

struct SampleOutcome {
  bool similar = false;
  bool searched = false;
  std::optional<RigidTransform> found;  // a motion from the search (step 2 or 3)
  long cached = -1;                     // index of the reused motion that matched
};

// A cloud point's disk radius in distances to its 4th nearest point: about 15 points in a full
// disk, so that a location at an edge has no point within the radius on its side only rarely.
constexpr double kSplatSpacings = 2.0;
// Share of a cloud ball's samples that may miss the other surface (gaps at corners).
constexpr double kCloudMissingFraction = 0.02;
// A cloud's corners and creases are fitted to noisy points: twice the nearest anchors are tried.
constexpr std::size_t kCloudAnchorFactor = 2;
// Two noisy clouds: the tolerance covers this many standard deviations of the difference of
// their noise (about 5 in 10000 samples beyond it).
constexpr double kNoiseTolerance = 3.5;

// A cloud's sampling statistics within eps = r / 4 (none for a mesh).
PointStatistics statistics_of(const SimilarityInput& input, double r) {
  return input.cloud ? point_statistics(*input.cloud, r / 4.0) : PointStatistics{};
}

// The surface index of one side: dense samples at spacing_r * r, queries up to eps = r / 4.
SurfaceIndex make_index(const SimilarityInput& input, const PointStatistics& statistics, double r,
                        const RSimilarityOptions& options, std::uint64_t seed) {
  const double eps = r / 4.0;
  if (input.mesh) return SurfaceIndex(*input.mesh, options.spacing_r * r, r, eps, seed);
  return SurfaceIndex(*input.cloud, std::min(eps, kSplatSpacings * statistics.spacing), options.spacing_r * r, r, eps);
}

class Matcher {
 public:
  Matcher(const SimilarityInput& exemplar, const SimilarityInput& candidate, double r, const RSimilarityOptions& options)
      : options_(options),
        r_(r),
        exemplar_statistics_(statistics_of(exemplar, r)),
        candidate_statistics_(statistics_of(candidate, r)),
        exemplar_index_(make_index(exemplar, exemplar_statistics_, r, options, options.seed)),
        candidate_index_(make_index(candidate, candidate_statistics_, r, options, options.seed + 1)),
        candidate_keypoints_(keypoint_anchors(candidate)),
        candidate_samples_(sample_anchors(candidate)),
        exemplar_keypoints_(keypoint_anchors(exemplar)),
        exemplar_samples_(sample_anchors(exemplar)) {
    const double eps = r / 4.0;
    tolerances_.r = r_;
    tolerances_.tolerance = std::min(options.tolerance_eps, 1.0) * eps;
    if (exemplar.cloud) {
      const double noise = std::hypot(exemplar_statistics_.noise, candidate_statistics_.noise);
      tolerances_.tolerance = std::min(eps, std::max(tolerances_.tolerance, kNoiseTolerance * noise));
    }
    tolerances_.min_cos = std::cos(options.normal_tolerance_degrees * std::numbers::pi / 180.0);
    tolerances_.icp_cutoff = eps;
    tolerances_.icp_iterations = options.icp_iterations;
    anchors_ = options.anchors;
    if (exemplar.cloud) {
      anchors_ *= kCloudAnchorFactor;
      tolerances_.max_missing_fraction = kCloudMissingFraction;
      tolerances_.min_cos = 0.0;  // any disk within the tolerance is surface: fitted normals blur at creases
    }
    probe_cutoff_ = std::min(2.0 * tolerances_.tolerance, eps);
    sort_by_dihedral(exemplar_keypoints_);
    sort_by_dihedral(exemplar_samples_);
    find_flat_disk();
  }

  double tolerance() const { return tolerances_.tolerance; }
  const SurfaceIndex& exemplar_index() const { return exemplar_index_; }
  const SurfaceIndex& candidate_index() const { return candidate_index_; }

  // Tries the reused motions (in the given order), then, if `search`, steps 2 and 3.
  SampleOutcome match(const SurfacePoint& y, const std::vector<Motion>& motions, const std::vector<std::size_t>& order,
                      bool search) const {
    SampleOutcome outcome;
    std::vector<std::uint32_t> ball, part, scratch;
    candidate_index_.gather_connected(y.position, y.normal, r_, tolerances_.tolerance, tolerances_.min_cos, ball, &part);
    const std::vector<std::uint32_t> probes = spread_probes(y.position, ball);
    for (std::size_t m : order) {
      const RigidTransform& t = motions[m].transform;
      if (!probes_touch(probes, t, tolerances_.tolerance, tolerances_.min_cos)) continue;
      if (neighbourhoods_match(candidate_index_, exemplar_index_, y, ball, t, tolerances_, scratch)) {
        outcome.similar = true;
        outcome.cached = static_cast<long>(m);
        return outcome;
      }
    }
    if (!search) return outcome;
    outcome.searched = true;
    // First only proposals that already put the whole ball within the tolerance (exact frames:
    // corners, straight edges, flat disks), then looser ones (curved lines) with a smaller budget.
    std::size_t attempts = 0, budget = options_.max_alignments;
    double cutoff = tolerances_.tolerance;
    auto attempt = [&](const RigidTransform& proposal) {
      if (attempts >= budget) return false;
      if (!probes_touch(probes, proposal, cutoff, tolerances_.min_cos) ||
          !probes_touch(ball, proposal, cutoff, tolerances_.min_cos))
        return false;
      ++attempts;
      const RigidTransform refined =
          refine_alignment(candidate_index_, exemplar_index_, y.position, ball, proposal, tolerances_);
      if (!neighbourhoods_match(candidate_index_, exemplar_index_, y, ball, refined, tolerances_, scratch))
        return false;
      outcome.similar = true;
      outcome.found = refined;
      return true;
    };
    if (flat_disk_ && is_flat(candidate_index_, y, ball)) {
      RigidTransform t;
      t.rotation = Eigen::Quaterniond::FromTwoVectors(y.normal, flat_disk_->normal).toRotationMatrix();
      t.translation = flat_disk_->position - t.rotation * y.position;
      if (attempt(t)) return outcome;
    }
    for (int round = 0; round < 2; ++round) {
      if (try_anchors(y.position, part, candidate_keypoints_, exemplar_keypoints_, attempt)) return outcome;
      if (try_anchors(y.position, part, candidate_samples_, exemplar_samples_, attempt)) return outcome;
      attempts = 0;
      budget = options_.max_loose_alignments;
      cutoff = probe_cutoff_;
    }
    return outcome;
  }

 private:
  // Up to 8 samples of the ball, spread out by farthest-point selection from y.
  std::vector<std::uint32_t> spread_probes(const Vec3& y, const std::vector<std::uint32_t>& ball) const {
    std::vector<std::uint32_t> probes;
    std::vector<double> distance(ball.size());
    for (std::size_t i = 0; i < ball.size(); ++i) distance[i] = (candidate_index_.samples()[ball[i]].position - y).norm();
    while (probes.size() < 8 && !ball.empty()) {
      const auto farthest = static_cast<std::size_t>(std::max_element(distance.begin(), distance.end()) - distance.begin());
      if (distance[farthest] <= 0.0) break;
      probes.push_back(ball[farthest]);
      const Vec3 chosen = candidate_index_.samples()[ball[farthest]].position;
      for (std::size_t i = 0; i < ball.size(); ++i)
        distance[i] = std::min(distance[i], (candidate_index_.samples()[ball[i]].position - chosen).norm());
    }
    return probes;
  }

  bool probes_touch(const std::vector<std::uint32_t>& probes, const RigidTransform& t, double cutoff, double min_cos) const {
    for (std::uint32_t i : probes) {
      const SurfacePoint& p = candidate_index_.samples()[i];
      if (!exemplar_index_.touches(t.apply(p.position), t.apply_direction(p.normal), cutoff, min_cos)) return false;
    }
    return true;
  }

  // Aligns the candidate anchors nearest to y on its neighbourhood (`part`: the triangles of its
  // connected part) with compatible exemplar anchors.
  template <class Attempt>
  bool try_anchors(const Vec3& y, const std::vector<std::uint32_t>& part, const std::vector<Anchor>& near,
                   const std::vector<Anchor>& far, Attempt& attempt) const {
    std::vector<std::pair<double, std::size_t>> nearest;
    for (std::size_t i = 0; i < near.size(); ++i) {
      const double d = (near[i].position - y).norm();
      if (d <= r_ && candidate_index_.near_any_of(near[i].position, tolerances_.tolerance, part)) nearest.emplace_back(d, i);
    }
    std::sort(nearest.begin(), nearest.end());
    const double tolerance = options_.dihedral_tolerance_degrees;
    auto compatible = [&](const Anchor& c, const Anchor& e) {
      return e.descriptor.kind == c.descriptor.kind &&
             std::abs(e.descriptor.dihedral_degrees - c.descriptor.dihedral_degrees) <= tolerance;
    };
    // The exemplar anchors whose dihedral key lies within the tolerance of c's.
    auto candidates_for = [&](const Anchor& c) {
      const auto begin = std::lower_bound(far.begin(), far.end(), std::round(c.descriptor.dihedral_degrees - tolerance),
                                          [](const Anchor& a, double value) { return dihedral_key(a) < value; });
      auto end = begin;
      while (end != far.end() && dihedral_key(*end) <= std::round(c.descriptor.dihedral_degrees + tolerance)) ++end;
      return std::make_pair(begin, end);
    };
    // Both tangent directions of one feature sample count as one anchor. Anchors without any
    // compatible exemplar anchor (a feature the exemplar lacks, e.g. a non-manifold seam of
    // coplanar faces) are passed over, so they do not use up the nearest-anchor budget.
    std::size_t used = 0;
    Vec3 last = Vec3::Constant(std::numeric_limits<double>::infinity());
    for (const auto& [d, i] : nearest) {
      const Anchor& c = near[i];
      const auto [begin, end] = candidates_for(c);
      if (std::none_of(begin, end, [&](const Anchor& e) { return compatible(c, e); })) continue;
      if (c.position != last && ++used > anchors_) break;
      last = c.position;
      for (auto e = begin; e != end; ++e)
        if (compatible(c, *e) && attempt(align(c, *e))) return true;
    }
    return false;
  }

  // True when every sample of `ball` lies within the tolerance of y's tangent plane with a
  // normal close to y's.
  bool is_flat(const SurfaceIndex& index, const SurfacePoint& y, const std::vector<std::uint32_t>& ball) const {
    return std::all_of(ball.begin(), ball.end(), [&](std::uint32_t i) {
      const SurfacePoint& p = index.samples()[i];
      return std::abs((p.position - y.position).dot(y.normal)) <= tolerances_.tolerance &&
             index.normals_agree(p.normal, y.normal, tolerances_.min_cos);
    });
  }

  // True when `ball` fills the disk of radius r around x: for a mesh, 80 % of the samples a full
  // disk holds; for a cloud, whose density is unknown, samples reach 0.85 r from x and their
  // centroid lies within 0.15 r of it.
  bool fills_disk(const SurfacePoint& x, const std::vector<std::uint32_t>& ball) const {
    const std::vector<SurfacePoint>& samples = exemplar_index_.samples();
    if (!exemplar_index_.is_cloud()) {
      const double h = options_.spacing_r * r_;
      return static_cast<double>(ball.size()) >= 0.8 * std::numbers::pi * r_ * r_ / (h * h);
    }
    if (ball.empty()) return false;
    Vec3 centroid = Vec3::Zero();
    double reach = 0.0;
    for (std::uint32_t i : ball) {
      centroid += samples[i].position;
      reach = std::max(reach, (samples[i].position - x.position).norm());
    }
    centroid /= static_cast<double>(ball.size());
    return reach >= 0.85 * r_ && (centroid - x.position).norm() <= 0.15 * r_;
  }

  // A point of the exemplar whose intrinsic r-neighbourhood is one full flat disk, for step 3:
  // tried at up to 1024 dense samples picked in a fixed pseudo-random order.
  void find_flat_disk() {
    const std::vector<SurfacePoint>& samples = exemplar_index_.samples();
    std::vector<std::uint32_t> ball;
    for (std::size_t k = 0; k < std::min<std::size_t>(1024, samples.size()); ++k) {
      const SurfacePoint& x = samples[splitmix64(k) % samples.size()];
      if (!exemplar_index_.gather_connected(x.position, x.normal, r_, tolerances_.tolerance, tolerances_.min_cos, ball) ||
          !fills_disk(x, ball))
        continue;
      if (is_flat(exemplar_index_, x, ball)) {
        flat_disk_ = x;
        return;
      }
    }
  }

  RSimilarityOptions options_;
  double r_;
  PointStatistics exemplar_statistics_, candidate_statistics_;  // clouds only
  SurfaceIndex exemplar_index_, candidate_index_;
  std::vector<Anchor> candidate_keypoints_, candidate_samples_, exemplar_keypoints_, exemplar_samples_;
  MatchTolerances tolerances_;
  std::size_t anchors_ = 0;  // nearest candidate anchors tried per test point
  double probe_cutoff_ = 0.0;
  std::optional<SurfacePoint> flat_disk_;
};

// Area-uniform test points on a mesh, or points of a cloud picked at random (with repeats),
// from one seed.
std::vector<SurfacePoint> test_points(const SimilarityInput& input, std::size_t count, std::uint64_t seed) {
  std::vector<SurfacePoint> points;
  if (input.cloud) {
    const std::vector<Vec3>& positions = input.cloud->positions;
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t k = splitmix64(seed ^ splitmix64(i)) % positions.size();
      points.push_back({positions[k], input.cloud->normals[k]});
    }
    return points;
  }
  const PointCloud cloud = sample_surface(*input.mesh, count, seed);
  points.reserve(cloud.positions.size());
  for (std::size_t i = 0; i < cloud.positions.size(); ++i) points.push_back({cloud.positions[i], cloud.normals[i]});
  return points;
}

// True when the side holds a mesh with triangles or a cloud with points, not both.
bool usable(const SimilarityInput& input) {
  if (input.mesh) return !input.cloud && input.feature_lines && !input.mesh->triangles.empty();
  return input.cloud && !input.cloud->positions.empty();
}

// Motion indices by hits (descending), then insertion order.
std::vector<std::size_t> usage_order(const std::vector<Motion>& motions) {
  std::vector<std::size_t> order(motions.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return motions[a].hits > motions[b].hits; });
  return order;
}

}  // namespace

RSimilarityResult estimate_r_similarity(const SimilarityInput& exemplar, const SimilarityInput& candidate, double r,
                                        const RSimilarityOptions& options, const ProgressCallback& progress) {
  if (!usable(exemplar) || !usable(candidate) || !exemplar.mesh != !candidate.mesh)
    throw InputError("r-similarity needs two triangle meshes or two point clouds");
  if (!(r > 0.0) || !std::isfinite(r)) throw InputError("r-similarity needs a positive radius r");
  if (options.samples == 0 || options.batch_size == 0 || !(options.spacing_r > 0.0) || !(options.tolerance_eps > 0.0))
    throw InputError("r-similarity options: samples, batch size, spacing and tolerance must be positive");
  report_progress(progress, "r-similarity", 0.0);
  const Matcher matcher(exemplar, candidate, r, options);
  RSimilarityResult result;
  result.r = r;
  result.tolerance = matcher.tolerance();
  result.dense_samples_exemplar = matcher.exemplar_index().samples().size();
  result.dense_samples_candidate = matcher.candidate_index().samples().size();

  const std::vector<SurfacePoint> points = test_points(candidate, options.samples, options.seed);
  result.samples = points.size();
  std::vector<Motion> motions{{RigidTransform{}, 0}};
  std::vector<SampleOutcome> outcomes(points.size());
  for (std::size_t begin = 0; begin < points.size(); begin += options.batch_size) {
    const std::size_t end = std::min(points.size(), begin + options.batch_size);
    const std::vector<std::size_t> order = usage_order(motions);
    tbb::parallel_for(begin, end, [&](std::size_t i) { outcomes[i] = matcher.match(points[i], motions, order, true); });
    for (std::size_t i = begin; i < end; ++i) {
      const SampleOutcome& outcome = outcomes[i];
      if (outcome.cached >= 0) ++motions[static_cast<std::size_t>(outcome.cached)].hits;
      if (!outcome.found || motions.size() >= options.max_motions) continue;
      const bool known = std::any_of(motions.begin(), motions.end(), [&](const Motion& m) {
        return same_motion(m.transform, *outcome.found, 0.01 * result.tolerance);
      });
      if (!known) motions.push_back({*outcome.found, 1});
    }
    report_progress(progress, "r-similarity", 0.9 * static_cast<double>(end) / static_cast<double>(points.size()));
  }
  // Points that failed before a motion that fits them was found get every motion once more.
  const std::vector<std::size_t> order = usage_order(motions);
  tbb::parallel_for(std::size_t{0}, points.size(), [&](std::size_t i) {
    if (!outcomes[i].similar) {
      const bool searched = outcomes[i].searched;
      outcomes[i] = matcher.match(points[i], motions, order, false);
      outcomes[i].searched = searched;
    }
  });
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (outcomes[i].similar)
      ++result.similar;
    else
      result.dissimilar_points.push_back(points[i].position);
    if (outcomes[i].searched) ++result.searched;
  }
  result.motions = motions.size();
  result.fraction = result.samples == 0 ? 1.0 : static_cast<double>(result.similar) / static_cast<double>(result.samples);
  report_progress(progress, "r-similarity", 1.0);
  return result;
}

}  // namespace dg
