#include "grammar/seam_curve.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace dg {
namespace {

// Where the misfit and the alignment look at a curve: its segments' ends and midpoints.
std::vector<Vec3> samples(const std::vector<Segment>& curve) {
  std::vector<Vec3> points;
  points.reserve(3 * curve.size());
  for (const Segment& s : curve) {
    points.push_back(s[0]);
    points.push_back(s[1]);
    points.push_back(0.5 * (s[0] + s[1]));
  }
  return points;
}

// A curve's segment ends.
std::vector<Vec3> samples_at_ends(const std::vector<Segment>& curve) {
  std::vector<Vec3> points;
  points.reserve(2 * curve.size());
  for (const Segment& s : curve) points.push_back(s[0]), points.push_back(s[1]);
  return points;
}

// A curve's segment ends, each as a segment of length 0 (to index them as a SegmentIndex).
std::vector<Segment> ends_as_segments(const std::vector<Segment>& curve) {
  std::vector<Segment> points;
  points.reserve(2 * curve.size());
  for (const Vec3& p : samples_at_ends(curve)) points.push_back({p, p});
  return points;
}

// The largest distance from a sample of `a` to the nearest segment of `b`, or infinity when
// some sample has no segment of `b` within `limit`.
double farthest_sample(const std::vector<Segment>& a, const std::vector<Segment>& b, double limit, double cell) {
  const SegmentIndex index(b, limit, cell);
  double farthest = 0.0;
  for (const Vec3& p : samples(a)) {
    // A point within the largest distance so far is enough: the sample cannot raise it.
    const std::optional<Vec3> q = index.nearest(p, farthest);
    const double distance = q ? (*q - p).norm() : std::numeric_limits<double>::infinity();
    if (distance > limit) return std::numeric_limits<double>::infinity();
    farthest = std::max(farthest, distance);
  }
  return farthest;
}

}  // namespace

std::vector<Segment> seam_segments(const TriangleMesh& mesh, const EdgeUsers& users,
                                   const std::vector<std::uint32_t>& piece, const std::vector<char>& inside) {
  std::vector<Segment> segments;
  for (std::uint32_t t : piece)
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t corner = 3 * t + k;
      bool meets_outside = false;
      for (std::uint32_t u = users.group_begin[corner]; u < users.group_end[corner] && !meets_outside; ++u)
        meets_outside = !inside[users.corners[u] / 3];
      if (!meets_outside) continue;
      segments.push_back({mesh.positions[mesh.triangles[t][k]], mesh.positions[mesh.triangles[t][(k + 1) % 3]]});
    }
  return segments;
}

double seam_misfit(const std::vector<Segment>& a, const std::vector<Segment>& b, double limit, double cell) {
  return std::max(farthest_sample(a, b, limit, cell), farthest_sample(b, a, limit, cell));
}

std::optional<RigidTransform> align_seam_curve(const std::vector<Segment>& moving, const std::vector<Segment>& reference,
                                               double reach, double cell) {
  if (moving.empty() || reference.empty()) return std::nullopt;
  // One least-squares step after `total`: both curves' samples (segment ends only, `by_ends`)
  // paired with the nearest sample or point of the other curve; nothing when one has no
  // partner within reach.
  const SegmentIndex on_reference(reference, reach, cell);
  const std::vector<Segment> reference_ends = ends_as_segments(reference);
  const SegmentIndex on_reference_ends(reference_ends, reach, cell);
  auto step = [&](const RigidTransform& total, bool by_ends) -> std::optional<RigidTransform> {
    std::vector<Segment> moved = moving;
    for (Segment& s : moved) s = {total.apply(s[0]), total.apply(s[1])};
    const std::vector<Segment> moved_ends = by_ends ? ends_as_segments(moved) : std::vector<Segment>{};
    const SegmentIndex on_moved(by_ends ? moved_ends : moved, reach, cell);
    std::vector<Vec3> from, to;
    auto pair_up = [&](const std::vector<Segment>& curve, const SegmentIndex& other, bool forward) {
      for (const Vec3& p : by_ends ? samples_at_ends(curve) : samples(curve)) {
        const std::optional<Vec3> q = other.nearest(p);
        if (!q || (*q - p).norm() > reach) return false;
        from.push_back(forward ? p : *q), to.push_back(forward ? *q : p);
      }
      return true;
    };
    if (!pair_up(moved, by_ends ? on_reference_ends : on_reference, true) || !pair_up(reference, on_moved, false))
      return std::nullopt;
    return fit_rigid_transform(from, to);
  };
  // Copies cut alike share their curve's vertices: while every segment end of each curve has
  // one of the other's within reach, pairing ends with ends finds the motion in a round or two.
  // Closest points on the segments then settle it, also for curves whose vertices differ.
  RigidTransform total;
  for (int round = 0; round < kSeamAlignEndRounds; ++round) {
    const std::optional<RigidTransform> by_ends = step(total, true);
    if (!by_ends) break;
    total = by_ends->after(total);
  }
  for (int round = 0; round < kSeamAlignIterations; ++round) {
    const std::optional<RigidTransform> by_points = step(total, false);
    if (!by_points) return std::nullopt;
    total = by_points->after(total);
  }
  return total;
}

}  // namespace dg
