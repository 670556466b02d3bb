#include "grammar/inference_terminals.h"

#include "grammar/inference_mean_shift.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <numeric>
#include <set>

namespace dg {

namespace {

constexpr double kDegree = std::numbers::pi / 180;

struct Sample {
  Vec2 point;
  double tangent = 0;    // radians
  double curvature = 0;  // signed, 1/length
};

// Uniform samples by arc length over all polylines of the element.
std::vector<Sample> sample_element(const ElementShape& shape, int count) {
  double total = 0;
  for (const auto& line : shape)
    for (std::size_t k = 1; k < line.size(); ++k) total += (line[k] - line[k - 1]).norm();
  std::vector<Sample> samples;
  if (total <= 0 || count <= 0) return samples;
  const double spacing = total / count;
  double walked = 0, next = spacing / 2;
  for (const auto& line : shape) {
    const std::size_t first = samples.size();
    for (std::size_t k = 1; k < line.size(); ++k) {
      const Vec2 piece = line[k] - line[k - 1];
      const double length = piece.norm();
      while (length > 0 && next <= walked + length && static_cast<int>(samples.size()) < count) {
        const double t = (next - walked) / length;
        samples.push_back(Sample{line[k - 1] + t * piece, std::atan2(piece.y(), piece.x()), 0});
        next += spacing;
      }
      walked += length;
    }
    for (std::size_t k = first; k < samples.size(); ++k) {
      const std::size_t lo = k > first ? k - 1 : k, hi = k + 1 < samples.size() ? k + 1 : k;
      if (hi == lo) continue;
      const double turn = std::remainder(samples[hi].tangent - samples[lo].tangent, 2 * std::numbers::pi);
      samples[k].curvature = turn / (spacing * static_cast<double>(hi - lo));
    }
  }
  return samples;
}

double diameter(const std::vector<Sample>& samples) {
  double best = 0;
  for (std::size_t i = 0; i < samples.size(); ++i)
    for (std::size_t j = i + 1; j < samples.size(); ++j) best = std::max(best, (samples[i].point - samples[j].point).norm());
  return best;
}

// Share of `b`'s points within `tolerance` of some mapped point of `a`.
double coverage(const std::vector<Vec2>& mapped_a, const std::vector<Sample>& b, double tolerance) {
  if (b.empty()) return 0;
  std::size_t hits = 0;
  for (const Sample& s : b) {
    for (const Vec2& p : mapped_a)
      if ((p - s.point).squaredNorm() <= tolerance * tolerance) {
        ++hits;
        break;
      }
  }
  return static_cast<double>(hits) / static_cast<double>(b.size());
}

struct Intrinsic {
  Vec2 start = Vec2::Zero();
  double angle_deg = 0;  // direction from the first point to the farthest point
  double reach = 0;      // distance to the farthest point
};

Intrinsic intrinsic_frame(const ElementShape& shape) {
  Intrinsic f;
  f.start = shape.front().front();
  for (const auto& line : shape)
    for (const Vec2& p : line) {
      const double d = (p - f.start).norm();
      if (d > f.reach * (1 + 1e-9)) {
        f.reach = d;
        f.angle_deg = std::atan2(p.y() - f.start.y(), p.x() - f.start.x()) / kDegree;
      }
    }
  return f;
}

bool is_segment(const ElementShape& shape) { return shape.size() == 1 && shape.front().size() == 2; }

// Maps a point of element a to element b by the intrinsic frames.
Vec2 map_by_frames(const Vec2& p, const Intrinsic& a, const Intrinsic& b) {
  const double rotation = (b.angle_deg - a.angle_deg) * kDegree, scale = b.reach / a.reach;
  const Eigen::Rotation2Dd r(rotation);
  return b.start + scale * (r * (p - a.start));
}

// Refines rotation and scale of an instance against its representative by a least-squares fit
// (Procrustes) of samples at equal arc-length positions, which is more precise than the
// farthest-point direction; kept only when the fitted samples agree within the match tolerance.
void refine_frame(const ElementShape& representative, const ElementShape& shape, const SimilarityOptions& options, InstanceFrame& frame) {
  const int count = 4 * options.samples;
  const std::vector<Sample> a = sample_element(representative, count), b = sample_element(shape, count);
  if (a.size() != b.size() || a.size() < 3) return;
  Vec2 ca = Vec2::Zero(), cb = Vec2::Zero();
  for (std::size_t k = 0; k < a.size(); ++k) ca += a[k].point, cb += b[k].point;
  ca /= static_cast<double>(a.size());
  cb /= static_cast<double>(b.size());
  double dot = 0, cross = 0, aa = 0, bb = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const Vec2 u = a[k].point - ca, v = b[k].point - cb;
    dot += u.dot(v);
    cross += u.x() * v.y() - u.y() * v.x();
    aa += u.squaredNorm();
    bb += v.squaredNorm();
  }
  if (aa <= 0 || bb <= 0) return;
  const double rotation = std::atan2(cross, dot), scale = std::sqrt(bb / aa);
  const Eigen::Rotation2Dd r(rotation);
  double worst = 0;
  for (std::size_t k = 0; k < a.size(); ++k) worst = std::max(worst, (cb + scale * (r * (a[k].point - ca)) - b[k].point).norm());
  if (worst > options.match_tolerance * std::sqrt(bb / static_cast<double>(b.size()))) return;
  frame.angle_deg = wrap_degrees(rotation / kDegree);
  frame.scale = scale;
}

}  // namespace

std::vector<Vec2> sample_points(const ElementShape& shape, int count) {
  std::vector<Vec2> points;
  for (const Sample& s : sample_element(shape, count)) points.push_back(s.point);
  if (points.empty() && !shape.empty() && !shape.front().empty()) points.push_back(shape.front().front());
  return points;
}

double element_similarity(const ElementShape& a, const ElementShape& b, const SimilarityOptions& options) {
  std::vector<Sample> sa = sample_element(a, options.samples), sb = sample_element(b, options.samples);
  if (sa.empty() || sb.empty()) return 0;
  const double da = diameter(sa), db = diameter(sb);
  if (da <= 0 || db <= 0) return 0;
  // Normalize both to unit diameter (the paper rescales b to a's size; the ratio is the same).
  for (Sample& s : sa) s.point /= da, s.curvature *= da;
  for (Sample& s : sb) s.point /= db, s.curvature *= db;
  // Votes: every pair of samples with similar curvature proposes the rotation and translation
  // that puts the sample of a onto the sample of b, tangent onto tangent (both path directions).
  std::vector<ShiftPoint> votes;
  std::vector<std::size_t> voter_b;
  const double bandwidth_t = options.match_tolerance, bandwidth_angle = options.vote_angle_deg * kDegree;
  for (const Sample& p : sa)
    for (std::size_t l = 0; l < sb.size(); ++l) {
      const Sample& q = sb[l];
      for (int reversed = 0; reversed < 2; ++reversed) {
        const double kq = reversed ? -q.curvature : q.curvature;
        if (std::abs(p.curvature - kq) > 0.25 * (std::abs(p.curvature) + std::abs(kq)) + 1.0) continue;
        const double theta = std::remainder(q.tangent + (reversed ? std::numbers::pi : 0) - p.tangent, 2 * std::numbers::pi);
        const Vec2 t = q.point - Eigen::Rotation2Dd(theta) * p.point;
        votes.push_back({theta / bandwidth_angle, t.x() / bandwidth_t, t.y() / bandwidth_t, 0});
        voter_b.push_back(l);
      }
    }
  if (votes.empty()) return 0;
  const ShiftClusters clusters = mean_shift(votes, 3, {2 * std::numbers::pi / bandwidth_angle, 0, 0, 0});
  if (clusters.centers.empty()) return 0;
  std::set<std::size_t> explained;
  for (std::size_t v = 0; v < votes.size(); ++v)
    if (clusters.labels[v] == 0) explained.insert(voter_b[v]);
  return static_cast<double>(explained.size()) / static_cast<double>(sb.size());
}

Instancing inverse_instancing(const std::vector<ElementShape>& elements, const SimilarityOptions& options) {
  Instancing result;
  struct Candidate {
    std::size_t element;
    Intrinsic frame;
  };
  std::vector<Candidate> candidates;
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const ElementShape& shape = elements[e];
    if (shape.empty() || shape.front().empty()) {
      ++result.skipped;
      continue;
    }
    const Intrinsic f = intrinsic_frame(shape);
    if (!(f.reach > 0)) {
      ++result.skipped;
      continue;
    }
    candidates.push_back({e, f});
  }
  // Canonical order: larger elements first (they become representatives), then by position.
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
    if (x.frame.reach != y.frame.reach) return x.frame.reach > y.frame.reach;
    if (x.frame.start.x() != y.frame.start.x()) return x.frame.start.x() < y.frame.start.x();
    if (x.frame.start.y() != y.frame.start.y()) return x.frame.start.y() < y.frame.start.y();
    return x.frame.angle_deg < y.frame.angle_deg;
  });
  const std::string letters = "ABCDEGHIJKLMNOQSTUVWXYZ";  // F, P and R are taken
  std::vector<Intrinsic> representatives;
  std::vector<std::size_t> representative_element;
  std::optional<std::size_t> segment_terminal;
  for (const Candidate& c : candidates) {
    const ElementShape& shape = elements[c.element];
    TerminalInstance instance;
    instance.element = c.element;
    if (is_segment(shape)) {
      if (!segment_terminal) {
        segment_terminal = result.terminals.size();
        result.terminals.push_back(Terminal{"F", true, c.frame.reach, {}});
        representatives.push_back(c.frame);
        representative_element.push_back(c.element);
      }
      instance.terminal = *segment_terminal;
      instance.frame = InstanceFrame{c.frame.start, wrap_degrees(c.frame.angle_deg), c.frame.reach / result.terminals[*segment_terminal].step};
      result.instances.push_back(instance);
      continue;
    }
    std::optional<std::size_t> match;
    double similarity = 0;
    for (std::size_t t = 0; t < result.terminals.size() && !match; ++t) {
      if (result.terminals[t].segment) continue;
      const ElementShape& rep = elements[representative_element[t]];
      // Quick test with the intrinsic frames, then the voting test of §4.1.
      std::vector<Vec2> mapped;
      for (const auto& line : rep)
        for (std::size_t k = 1; k < line.size(); ++k)
          for (int j = 0; j < 4; ++j)
            mapped.push_back(map_by_frames(line[k - 1] + (line[k] - line[k - 1]) * (j / 4.0), representatives[t], c.frame));
      const std::vector<Sample> samples = sample_element(shape, options.samples);
      double phi = coverage(mapped, samples, options.match_tolerance * 2 * c.frame.reach);
      if (phi <= options.threshold) phi = element_similarity(rep, shape, options);
      if (phi > options.threshold) match = t, similarity = phi;
    }
    if (!match) {
      const std::size_t index = result.terminals.size() - (segment_terminal ? 1 : 0);
      Terminal terminal;
      terminal.symbol = index < letters.size() ? std::string(1, letters[index]) : std::string("A").append(std::to_string(index));
      for (const auto& line : shape) {  // the representative's frame is aligned with the drawing
        std::vector<Vec2> local;
        for (const Vec2& p : line) local.push_back(p - c.frame.start);
        terminal.motif.push_back(std::move(local));
      }
      match = result.terminals.size();
      similarity = 1;
      result.terminals.push_back(std::move(terminal));
      representatives.push_back(c.frame);
      representative_element.push_back(c.element);
    }
    const Intrinsic& rep = representatives[*match];
    instance.terminal = *match;
    instance.similarity = similarity;
    instance.frame = InstanceFrame{c.frame.start, wrap_degrees(c.frame.angle_deg - rep.angle_deg), c.frame.reach / rep.reach};
    refine_frame(elements[representative_element[*match]], shape, options, instance.frame);
    result.instances.push_back(instance);
  }
  std::sort(result.instances.begin(), result.instances.end(), [](const TerminalInstance& x, const TerminalInstance& y) {
    const Vec2 &p = x.frame.position, &q = y.frame.position;
    if (p.x() != q.x()) return p.x() < q.x();
    if (p.y() != q.y()) return p.y() < q.y();
    if (x.frame.angle_deg != y.frame.angle_deg) return x.frame.angle_deg < y.frame.angle_deg;
    return x.frame.scale < y.frame.scale;
  });
  return result;
}

}  // namespace dg
