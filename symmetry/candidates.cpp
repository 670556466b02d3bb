#include "symmetry/candidates.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <unordered_map>

namespace dg {
namespace {

Mat3 frame_matrix(const Vec3& tangent, const Vec3& normal, const Vec3& binormal) {
  Mat3 frame;
  frame.col(0) = tangent;
  frame.col(1) = normal;
  frame.col(2) = binormal;
  return frame;
}

bool compatible(const FeatureDescriptor& a, const FeatureDescriptor& b, double dihedral_tolerance) {
  if (a.kind != b.kind) return false;
  if (std::abs(a.dihedral_degrees - b.dihedral_degrees) > dihedral_tolerance) return false;
  const double curvature_scale = std::max(std::abs(a.curvature), std::abs(b.curvature));
  return std::abs(a.curvature - b.curvature) <= 0.25 * curvature_scale + 1e-9;
}

// Spatial hash of keypoints with cells of size `cell`.
class KeypointGrid {
 public:
  KeypointGrid(const std::vector<Keypoint>& keypoints, double cell) : keypoints_(keypoints), cell_(cell) {
    for (std::uint32_t i = 0; i < keypoints.size(); ++i) buckets_[key(keypoints[i].position)].push_back(i);
  }

  // Nearest keypoint to p within `radius` (<= cell) whose descriptor is compatible and whose
  // frame agrees with `tangent` and `normal`, or -1. Several keypoints can share a position (the
  // ends of lines meeting at a corner); the frame picks the right one.
  long nearest(const Vec3& p, const FeatureDescriptor& descriptor, const Vec3& tangent, const Vec3& normal, double radius,
               double dihedral_tolerance) const {
    long best = -1;
    double best_distance = radius;
    // Only the cells the ball of `radius` around p overlaps (at most two along each axis).
    const auto low = coords(p - Vec3::Constant(radius)), high = coords(p + Vec3::Constant(radius));
    for (std::int64_t x = low[0]; x <= high[0]; ++x)
      for (std::int64_t y = low[1]; y <= high[1]; ++y)
        for (std::int64_t z = low[2]; z <= high[2]; ++z) {
          const auto found = buckets_.find(pack(x, y, z));
          if (found == buckets_.end()) continue;
          for (std::uint32_t i : found->second) {
            const double d = (keypoints_[i].position - p).norm();
            if (d <= best_distance && compatible(keypoints_[i].descriptor, descriptor, dihedral_tolerance) &&
                keypoints_[i].tangent.dot(tangent) > 0.95 && keypoints_[i].normal.dot(normal) > 0.95 &&
                (best < 0 || d < best_distance || i < static_cast<std::uint32_t>(best))) {
              best = i;
              best_distance = d;
            }
          }
        }
    return best;
  }

 private:
  std::array<std::int64_t, 3> coords(const Vec3& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x() / cell_)), static_cast<std::int64_t>(std::floor(p.y() / cell_)),
            static_cast<std::int64_t>(std::floor(p.z() / cell_))};
  }
  static std::uint64_t pack(std::int64_t x, std::int64_t y, std::int64_t z) {
    const auto part = [](std::int64_t v) { return static_cast<std::uint64_t>(v + (1 << 20)) & 0x1FFFFF; };
    return (part(x) << 42) | (part(y) << 21) | part(z);
  }
  std::uint64_t key(const Vec3& p) const {
    const auto c = coords(p);
    return pack(c[0], c[1], c[2]);
  }

  const std::vector<Keypoint>& keypoints_;
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> buckets_;
};

// 6-D voting key: quantized rotation vector and displacement of the centre, on a grid shifted
// by `shift` bins (0 or 0.5) so that every tight cluster falls inside one bin of some grid.
struct VoteKey {
  std::array<std::int32_t, 6> bins;
  auto operator<=>(const VoteKey&) const = default;
};

VoteKey vote_key(const RigidTransform& t, const Vec3& centre, double angle_bin, double translation_bin, double shift) {
  const Eigen::AngleAxisd angle_axis(t.rotation);
  const Vec3 rotation_vector = angle_axis.angle() * angle_axis.axis();
  const Vec3 displacement = t.apply(centre) - centre;
  VoteKey key;
  for (int k = 0; k < 3; ++k) {
    key.bins[k] = static_cast<std::int32_t>(std::floor(rotation_vector[k] / angle_bin + shift));
    key.bins[k + 3] = static_cast<std::int32_t>(std::floor(displacement[k] / translation_bin + shift));
  }
  return key;
}

// Keypoint matches of T: every keypoint whose image lands on a compatible keypoint.
std::vector<std::pair<std::uint32_t, std::uint32_t>> matches_of(const RigidTransform& t, const std::vector<Keypoint>& keypoints,
                                                                const KeypointGrid& grid, double radius,
                                                                double dihedral_tolerance) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> matches;
  for (std::uint32_t i = 0; i < keypoints.size(); ++i) {
    const long j = grid.nearest(t.apply(keypoints[i].position), keypoints[i].descriptor, t.rotation * keypoints[i].tangent,
                                t.rotation * keypoints[i].normal, radius, dihedral_tolerance);
    if (j >= 0 && static_cast<std::uint32_t>(j) != i) matches.emplace_back(i, static_cast<std::uint32_t>(j));
  }
  return matches;
}

// Indices of the residuals (target minus mapped source) within `bandwidth` of their densest
// mode: the matches of one repeat when two repeats of slightly different pitch lie within the
// match radius (a colonnade whose shafts and capitals were placed 0.4 eps apart in pitch).
// Mean shift from the voxel of side `bandwidth` whose 27 neighbours hold the most residuals
// (the lowest voxel on ties).
std::vector<std::size_t> dominant_mode(const std::vector<Vec3>& residuals, double bandwidth) {
  std::map<std::array<std::int64_t, 3>, std::size_t> counts;
  auto voxel = [&](const Vec3& v) {
    return std::array<std::int64_t, 3>{static_cast<std::int64_t>(std::floor(v.x() / bandwidth)),
                                       static_cast<std::int64_t>(std::floor(v.y() / bandwidth)),
                                       static_cast<std::int64_t>(std::floor(v.z() / bandwidth))};
  };
  for (const Vec3& v : residuals) ++counts[voxel(v)];
  std::array<std::int64_t, 3> best_voxel{};
  std::size_t best_count = 0;
  for (const auto& [cell, count] : counts) {
    std::size_t around = 0;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto found = counts.find({cell[0] + dx, cell[1] + dy, cell[2] + dz});
          if (found != counts.end()) around += found->second;
        }
    if (around > best_count) {
      best_count = around;
      best_voxel = cell;
    }
  }
  Vec3 mode = (Vec3(best_voxel[0], best_voxel[1], best_voxel[2]) + Vec3::Constant(0.5)) * bandwidth;
  std::vector<std::size_t> members;
  for (int step = 0; step < 4; ++step) {
    members.clear();
    Vec3 sum = Vec3::Zero();
    for (std::size_t m = 0; m < residuals.size(); ++m)
      if ((residuals[m] - mode).norm() <= bandwidth) {
        members.push_back(m);
        sum += residuals[m];
      }
    if (members.empty()) break;
    mode = sum / static_cast<double>(members.size());
  }
  return members;
}

// ICP on keypoints: refit T to its matches with a shrinking match radius, so that pairs that
// only roughly agree (different parts that happen to lie close) drop out and exact repeats fit
// to rounding precision. With `follow_mode`, each round fits only the matches in the dominant
// residual mode, of half the next round's radius. `second_round_support` receives the matches
// at 0.25 eps (0 when the rounds stop before).
Candidate refine_rounds(RigidTransform t, const std::vector<Keypoint>& keypoints, const KeypointGrid& grid, double eps,
                        double dihedral_tolerance, bool follow_mode, std::size_t* second_round_support = nullptr) {
  constexpr std::array<double, 4> radii{1.0, 0.25, 0.1, 0.1};  // in eps (eps scaled by match_radius_scale)
  Candidate candidate;
  candidate.transform = t;
  if (second_round_support) *second_round_support = 0;
  for (std::size_t round = 0; round < radii.size(); ++round) {
    candidate.matches = matches_of(candidate.transform, keypoints, grid, radii[round] * eps, dihedral_tolerance);
    if (round == 1 && second_round_support) *second_round_support = candidate.matches.size();
    if (candidate.matches.size() < 3) break;
    std::vector<Vec3> from, to;
    for (const auto& [i, j] : candidate.matches) {
      from.push_back(keypoints[i].position);
      to.push_back(keypoints[j].position);
    }
    if (follow_mode) {
      std::vector<Vec3> residuals;
      for (std::size_t m = 0; m < from.size(); ++m) residuals.push_back(to[m] - candidate.transform.apply(from[m]));
      const std::vector<std::size_t> members = dominant_mode(residuals, 0.5 * radii[std::min(round + 1, radii.size() - 1)] * eps);
      if (members.size() < 3) break;
      std::vector<Vec3> mode_from, mode_to;
      for (std::size_t m : members) {
        mode_from.push_back(from[m]);
        mode_to.push_back(to[m]);
      }
      from = std::move(mode_from);
      to = std::move(mode_to);
    }
    candidate.transform = fit_rigid_transform(from, to);
  }
  return candidate;
}

// refine_rounds over all matches; when the support collapses as the radius narrows (to under a
// quarter of the 0.25 eps round's), the fit averaged two nearby repeats into a motion that fits
// neither, and the rounds are run again following the dominant mode: the better one is kept.
Candidate refine(RigidTransform t, const std::vector<Keypoint>& keypoints, const KeypointGrid& grid, double eps,
                 double dihedral_tolerance) {
  std::size_t second_round_support = 0;
  Candidate plain = refine_rounds(t, keypoints, grid, eps, dihedral_tolerance, false, &second_round_support);
  if (4 * plain.matches.size() >= second_round_support) return plain;
  Candidate moded = refine_rounds(t, keypoints, grid, eps, dihedral_tolerance, true);
  return moded.matches.size() > plain.matches.size() ? moded : plain;
}

// Puts a candidate's motion into canonical form, swapping its matches when it is inverted.
void make_canonical(Candidate& c, double slide_tolerance) {
  const RigidTransform canonical = canonical_motion(c.transform, slide_tolerance);
  if (!(canonical.rotation.isApprox(c.transform.rotation) && canonical.translation.isApprox(c.transform.translation)))
    for (auto& [i, j] : c.matches) std::swap(i, j);
  c.transform = canonical;
}

// The keypoint at a feature-line sample: its position, frame and descriptor.
Keypoint keypoint_of(const FeatureSample& s) { return {s.position, s.tangent, s.normal, s.binormal, s.descriptor}; }

}  // namespace

Candidate refine_candidate(const RigidTransform& transform, const std::vector<Keypoint>& keypoints,
                           const CandidateOptions& options) {
  const KeypointGrid grid(keypoints, options.match_radius_scale * options.eps);
  Candidate c = refine(transform, keypoints, grid, options.match_radius_scale * options.eps, options.dihedral_tolerance_degrees);
  make_canonical(c, 0.5 * options.eps);
  return c;
}

std::vector<Keypoint> feature_keypoints(const FeatureLines& lines) {
  std::vector<Keypoint> keypoints;
  const auto& samples = lines.samples;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const FeatureSample& s = samples[i];
    if (lines.lines[s.line].closed) continue;
    const bool first = i == 0 || samples[i - 1].line != s.line;
    const bool last = i + 1 == samples.size() || samples[i + 1].line != s.line;
    if (!first && !last) continue;
    Keypoint k = keypoint_of(s);
    if (last && !first) {  // the tangent points into the line at both ends
      k.tangent = -k.tangent;
      k.binormal = -k.binormal;
    }
    keypoints.push_back(k);
    if (first && last) {  // a one-sample line: also the other orientation
      Keypoint reversed = k;
      reversed.tangent = -k.tangent;
      reversed.binormal = -k.binormal;
      keypoints.push_back(reversed);
    }
  }
  return keypoints;
}

std::vector<Keypoint> loop_keypoints(const FeatureLines& lines, const TriangleMesh& mesh) {
  std::vector<Keypoint> keypoints;
  for (std::uint32_t l = 0; l < lines.lines.size(); ++l) {
    const FeatureLine& line = lines.lines[l];
    if (!line.closed) continue;
    const std::size_t n = line.vertices.size();
    if (n < 3 || line.normals.size() < n) continue;
    std::vector<Vec3> points;
    for (std::uint32_t v : line.vertices) points.push_back(mesh.positions[v]);
    for (std::size_t k = 0; k < n; ++k) {
      // Edge e runs from vertex e to vertex e + 1; vertex k starts edge k and ends edge k - 1.
      for (const auto& [edge, forward] : {std::pair{k, true}, std::pair{(k + n - 1) % n, false}}) {
        const Vec3 along = points[(edge + 1) % n] - points[edge];
        if (along.norm() <= 0.0) continue;
        keypoints.push_back(keypoint_of(sample_on_edge(line, l, edge, points[k], (forward ? along : Vec3(-along)).normalized(),
                                                       vertex_curvature(points, true, k))));
      }
    }
  }
  return keypoints;
}

RigidTransform canonical_motion(const RigidTransform& transform, double slide_tolerance) {
  // Below this angle (radians) a motion counts as a translation when choosing its direction.
  constexpr double translation_angle = 1e-3;
  const double angle = transform.angle();
  Vec3 axis = angle < translation_angle ? transform.translation : transform.axis();
  // Components below this fraction of the length are fitting noise (a scan's translation along
  // z came out as (3e-4, 0, -3)) and do not choose the orientation.
  constexpr double noise = 1e-3;
  auto reference_sign = [&](const Vec3& v) {
    for (int k = 0; k < 3; ++k)
      if (std::abs(v[k]) > noise * v.norm()) return v[k] > 0.0 ? 1.0 : -1.0;
    return 1.0;
  };
  axis *= reference_sign(axis);  // oriented by its first clearly non-zero component
  bool keep;
  if (angle < translation_angle) {
    keep = transform.translation.dot(axis) >= 0.0;
  } else {
    const Eigen::AngleAxisd angle_axis(transform.rotation);
    const double signed_angle = angle_axis.axis().dot(axis) >= 0.0 ? angle_axis.angle() : -angle_axis.angle();
    const double slide = transform.translation.dot(axis);
    if (std::abs(slide) < slide_tolerance)
      keep = signed_angle > 0.0 || std::abs(std::abs(signed_angle) - std::numbers::pi) < 1e-9;  // rotation
    else
      keep = slide > 0.0;  // screw
  }
  return keep ? transform : transform.inverse();
}

std::vector<Candidate> find_candidates(const std::vector<Keypoint>& keypoints, const Vec3& centre,
                                       const CandidateOptions& options, CandidateStats* stats) {
  CandidateStats local;
  local.keypoints = keypoints.size();
  std::vector<Candidate> result;
  if (keypoints.size() < 2 || !(options.eps > 0.0)) {
    if (stats) *stats = local;
    return result;
  }
  const double eps = options.eps;
  const std::size_t stride = std::max<std::size_t>(1, (keypoints.size() + options.max_sources - 1) / options.max_sources);
  std::vector<std::uint32_t> sources;
  for (std::size_t i = 0; i < keypoints.size(); i += stride) sources.push_back(static_cast<std::uint32_t>(i));

  // Frame-to-frame motions for compatible (source, target) pairs, voted on two shifted grids.
  // Votes keep only the pair; the motion is recomputed when a peak is averaged. When the pairs
  // would exceed the budget, fewer sources are used (evenly spread over the keypoints).
  std::vector<std::size_t> compatible_counts(sources.size(), 0);
  tbb::parallel_for(std::size_t(0), sources.size(), [&](std::size_t s) {
    for (const Keypoint& b : keypoints)
      compatible_counts[s] += compatible(keypoints[sources[s]].descriptor, b.descriptor, options.dihedral_tolerance_degrees) ? 1 : 0;
  });
  std::size_t total_pairs = 0;
  for (std::size_t c : compatible_counts) total_pairs += c;
  if (total_pairs > options.max_pairs) {
    const std::size_t keep = std::max<std::size_t>(1, sources.size() * options.max_pairs / total_pairs);
    std::vector<std::uint32_t> fewer;
    for (std::size_t i = 0; i < keep; ++i) fewer.push_back(sources[i * sources.size() / keep]);
    sources = std::move(fewer);
  }
  auto pair_motion = [&](std::uint32_t source, std::uint32_t target) {
    const Keypoint& a = keypoints[source];
    const Keypoint& b = keypoints[target];
    RigidTransform t;
    t.rotation = frame_matrix(b.tangent, b.normal, b.binormal) * frame_matrix(a.tangent, a.normal, a.binormal).transpose();
    if (t.angle() < options.snap_to_translation_radians) t.rotation = Mat3::Identity();
    t.translation = b.position - t.rotation * a.position;
    return t;
  };
  const double translation_bin = options.translation_bin_eps * eps;
  struct Vote {
    VoteKey key;
    std::uint32_t source, target;
    bool operator<(const Vote& other) const {
      return std::tie(key, source, target) < std::tie(other.key, other.source, other.target);
    }
  };
  std::vector<std::vector<Vote>> per_source(sources.size());
  tbb::parallel_for(std::size_t(0), sources.size(), [&](std::size_t s) {
    const Keypoint& a = keypoints[sources[s]];
    for (std::uint32_t j = 0; j < keypoints.size(); ++j) {
      if (j == sources[s] || !compatible(a.descriptor, keypoints[j].descriptor, options.dihedral_tolerance_degrees)) continue;
      const RigidTransform t = pair_motion(sources[s], j);
      if ((t.apply(centre) - centre).norm() < 0.5 * eps && t.angle() < options.angle_bin_radians) continue;  // identity
      for (double shift : {0.0, 0.5})
        per_source[s].push_back({vote_key(t, centre, options.angle_bin_radians, translation_bin, shift), sources[s], j});
    }
  });
  std::vector<Vote> votes;
  for (auto& v : per_source) {
    votes.insert(votes.end(), v.begin(), v.end());
    std::vector<Vote>().swap(v);
  }
  local.pair_transforms = votes.size() / 2;
  tbb::parallel_sort(votes.begin(), votes.end());

  // Peaks: runs of equal keys with enough votes, largest first (ties by key: deterministic).
  std::vector<std::pair<std::size_t, std::size_t>> peaks;  // (size, first vote)
  for (std::size_t i = 0; i < votes.size();) {
    std::size_t j = i;
    while (j < votes.size() && votes[j].key == votes[i].key) ++j;
    if (j - i >= options.min_support) peaks.emplace_back(j - i, i);
    i = j;
  }
  std::stable_sort(peaks.begin(), peaks.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  const std::size_t max_peaks = 400;
  if (peaks.size() > max_peaks) peaks.resize(max_peaks);
  local.peaks = peaks.size();

  const KeypointGrid grid(keypoints, options.match_radius_scale * eps);
  std::vector<Candidate> refined(peaks.size());
  tbb::parallel_for(std::size_t(0), peaks.size(), [&](std::size_t p) {
    // Mean of the bin's motions (rotation averaged through the matrix, re-orthonormalized).
    Mat4 sum = Mat4::Zero();
    for (std::size_t v = peaks[p].second; v < peaks[p].second + peaks[p].first; ++v)
      sum += pair_motion(votes[v].source, votes[v].target).matrix();
    const RigidTransform mean = rigid_from_matrix(sum / static_cast<double>(peaks[p].first));
    refined[p] = refine(mean, keypoints, grid, options.match_radius_scale * eps, options.dihedral_tolerance_degrees);
  });

  const double slide_tolerance = 0.5 * eps;
  for (Candidate& c : refined) {
    if (c.matches.size() < options.min_support) continue;
    if ((c.transform.apply(centre) - centre).norm() < 0.5 * eps && c.transform.angle() < options.angle_bin_radians) continue;
    make_canonical(c, slide_tolerance);
    const RigidTransform& canonical = c.transform;
    bool duplicate = false;
    for (const Candidate& kept : result)
      if (same_motion(kept.transform, canonical, centre, eps)) {
        duplicate = true;
        break;
      }
    if (duplicate) continue;
    result.push_back(std::move(c));
  }
  std::stable_sort(result.begin(), result.end(),
                   [](const Candidate& x, const Candidate& y) { return x.matches.size() > y.matches.size(); });
  local.candidates = result.size();
  if (stats) *stats = local;
  return result;
}

}  // namespace dg
