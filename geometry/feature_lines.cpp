#include "geometry/feature_lines.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dg {
namespace {

// Feature edges around each vertex, in CSR form.
struct VertexEdges {
  std::vector<std::uint32_t> offsets, edges;

  VertexEdges(std::size_t vertex_count, const std::vector<FeatureEdge>& features) : offsets(vertex_count + 1, 0) {
    for (const FeatureEdge& e : features) {
      ++offsets[e.v0 + 1];
      ++offsets[e.v1 + 1];
    }
    for (std::size_t v = 0; v < vertex_count; ++v) offsets[v + 1] += offsets[v];
    edges.resize(offsets.back());
    std::vector<std::uint32_t> fill(offsets.begin(), offsets.end() - 1);
    for (std::uint32_t i = 0; i < features.size(); ++i) {
      edges[fill[features[i].v0]++] = i;
      edges[fill[features[i].v1]++] = i;
    }
  }
  std::size_t degree(std::uint32_t v) const { return offsets[v + 1] - offsets[v]; }
};

std::uint32_t other_end(const FeatureEdge& e, std::uint32_t v) { return e.v0 == v ? e.v1 : e.v0; }

// Lines run along edges of one class: boundary, material border, or crease (sharp and
// non-manifold edges chain together).
EdgeKind line_class(EdgeKind kind) { return kind == EdgeKind::non_manifold ? EdgeKind::sharp : kind; }

class LineTracer {
 public:
  LineTracer(const TriangleMesh& mesh, const std::vector<FeatureEdge>& features, double corner_angle_degrees)
      : mesh_(mesh), features_(features), around_(mesh.positions.size(), features), used_(features.size(), false),
        cos_corner_(std::cos(corner_angle_degrees * std::numbers::pi / 180.0)) {}

  std::vector<FeatureLine> trace() {
    std::vector<FeatureLine> lines;
    // Open lines first, started at every line end, then the remaining loops.
    for (std::uint32_t v = 0; v < mesh_.positions.size(); ++v)
      for (std::uint32_t k = around_.offsets[v]; k < around_.offsets[v + 1]; ++k) {
        const std::uint32_t e = around_.edges[k];
        if (!used_[e] && is_line_end(v, e)) lines.push_back(follow(v, e));
      }
    for (std::uint32_t e = 0; e < features_.size(); ++e)
      if (!used_[e]) lines.push_back(follow(features_[e].v0, e));
    return lines;
  }

 private:
  // The unique continuation of edge `e` through vertex v, or -1 when the line ends at v.
  long continuation(std::uint32_t v, std::uint32_t e) const {
    if (around_.degree(v) != 2) return -1;
    const std::uint32_t first = around_.edges[around_.offsets[v]];
    const std::uint32_t next = first == e ? around_.edges[around_.offsets[v] + 1] : first;
    if (line_class(features_[next].kind) != line_class(features_[e].kind)) return -1;
    const Vec3 in = (mesh_.positions[v] - mesh_.positions[other_end(features_[e], v)]).normalized();
    const Vec3 out = (mesh_.positions[other_end(features_[next], v)] - mesh_.positions[v]).normalized();
    if (in.dot(out) < cos_corner_) return -1;
    return next;
  }

  bool is_line_end(std::uint32_t v, std::uint32_t e) const { return continuation(v, e) < 0; }

  FeatureLine follow(std::uint32_t start, std::uint32_t e) {
    FeatureLine line;
    line.kind = line_class(features_[e].kind);
    line.vertices.push_back(start);
    std::uint32_t v = start;
    while (true) {
      used_[e] = true;
      const FeatureEdge& edge = features_[e];
      const std::uint32_t w = other_end(edge, v);
      line.normals.push_back(edge.normal);
      line.dihedrals.push_back(edge.dihedral_degrees);
      line.length += (mesh_.positions[w] - mesh_.positions[v]).norm();
      if (w == start) {
        line.closed = true;
        break;
      }
      line.vertices.push_back(w);
      const long next = continuation(w, e);
      if (next < 0 || used_[static_cast<std::size_t>(next)]) break;
      v = w;
      e = static_cast<std::uint32_t>(next);
    }
    return line;
  }

  const TriangleMesh& mesh_;
  const std::vector<FeatureEdge>& features_;
  VertexEdges around_;
  std::vector<bool> used_;
  double cos_corner_;
};

void sample_line(const TriangleMesh& mesh, std::uint32_t line_index, const FeatureLine& line, double spacing,
                 std::vector<FeatureSample>& samples) {
  std::vector<Vec3> points;
  for (std::uint32_t v : line.vertices) points.push_back(mesh.positions[v]);
  const std::size_t segments = line.normals.size();
  if (line.length <= 0.0 || segments == 0) return;
  const std::size_t intervals = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(line.length / spacing)));
  const std::size_t count = line.closed ? intervals : intervals + 1;
  const double step = line.length / static_cast<double>(intervals);
  std::size_t segment = 0;
  double segment_start = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const double s = std::min(step * static_cast<double>(i), line.length);
    auto segment_end = [&](std::size_t j) {
      return (points[(j + 1) % points.size()] - points[j]).norm();
    };
    while (segment + 1 < segments && s > segment_start + segment_end(segment)) {
      segment_start += segment_end(segment);
      ++segment;
    }
    const Vec3& a = points[segment];
    const Vec3& b = points[(segment + 1) % points.size()];
    const double length = (b - a).norm();
    if (length <= 0.0) continue;
    const double t = std::clamp((s - segment_start) / length, 0.0, 1.0);
    const std::size_t nearest = t < 0.5 ? segment : (segment + 1) % points.size();
    samples.push_back(sample_on_edge(line, line_index, segment, a + t * (b - a), (b - a) / length,
                                     vertex_curvature(points, line.closed, nearest)));
  }
}

}  // namespace

FeatureSample sample_on_edge(const FeatureLine& line, std::uint32_t line_index, std::size_t edge, const Vec3& position,
                             const Vec3& tangent, double curvature) {
  FeatureSample sample;
  sample.position = position;
  sample.tangent = tangent;
  Vec3 normal = line.normals[edge] - line.normals[edge].dot(tangent) * tangent;
  if (normal.norm() < 1e-9) normal = tangent.unitOrthogonal();
  sample.normal = normal.normalized();
  sample.binormal = tangent.cross(sample.normal);
  sample.line = line_index;
  sample.descriptor.dihedral_degrees = line.dihedrals[edge];
  sample.descriptor.kind = line.kind;
  sample.descriptor.curvature = curvature;
  return sample;
}

double vertex_curvature(const std::vector<Vec3>& points, bool closed, std::size_t k) {
  const std::size_t n = points.size();
  if (!closed && (k == 0 || k + 1 == n)) return 0.0;
  const Vec3& prev = points[(k + n - 1) % n];
  const Vec3& next = points[(k + 1) % n];
  const Vec3 in = points[k] - prev, out = next - points[k];
  const double lengths = in.norm() + out.norm();
  if (lengths <= 0.0) return 0.0;
  const double cosine = std::clamp(in.normalized().dot(out.normalized()), -1.0, 1.0);
  return 2.0 * std::acos(cosine) / lengths;
}

double FeatureLines::total_length() const {
  double sum = 0.0;
  for (const FeatureLine& line : lines) sum += line.length;
  return sum;
}

FeatureLines extract_feature_lines(const TriangleMesh& mesh, const std::vector<FeatureEdge>& features, double spacing,
                                   double corner_angle_degrees) {
  FeatureLines result;
  result.lines = LineTracer(mesh, features, corner_angle_degrees).trace();
  for (std::uint32_t i = 0; i < result.lines.size(); ++i) sample_line(mesh, i, result.lines[i], spacing, result.samples);
  return result;
}

}  // namespace dg
