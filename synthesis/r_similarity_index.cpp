#include "synthesis/r_similarity_index.h"

#include "geometry/errors.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_set>

namespace dg {
namespace {

double unit(std::uint64_t& state) {
  state = splitmix64(state);
  return static_cast<double>(state >> 11) * 0x1.0p-53;
}

constexpr std::int64_t kKeyBias = 1 << 20;

}  // namespace

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

SurfaceIndex::SurfaceIndex(const TriangleMesh& mesh, double spacing, double gather_radius, double max_cutoff,
                           std::uint64_t seed)
    : mesh_(&mesh), cell_(gather_radius), triangle_cell_(2.0 * max_cutoff) {
  element_normals_.reserve(mesh.triangles.size());
  std::vector<SurfacePoint> points;
  std::vector<std::uint32_t> triangles_of_points;
  const double inverse_cell_area = 1.0 / (spacing * spacing);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3 area_vector = mesh.area_vector(t);
    const double length = area_vector.norm();
    const Vec3 normal = length > 0.0 ? Vec3(area_vector / length) : Vec3::UnitZ();
    element_normals_.push_back(normal);
    std::uint64_t state = splitmix64(seed ^ splitmix64(t));
    const double expected = 0.5 * length * inverse_cell_area;
    const auto count = static_cast<std::size_t>(std::floor(expected + unit(state)));
    const auto [a, b, c] = mesh.corners(t);
    for (std::size_t i = 0; i < count; ++i) {
      const double s = std::sqrt(unit(state)), u = unit(state);
      points.push_back({(1.0 - s) * a + s * (1.0 - u) * b + s * u * c, normal});
      triangles_of_points.push_back(static_cast<std::uint32_t>(t));
    }
  }
  set_samples(std::move(points), std::move(triangles_of_points));
  build_triangle_grid(max_cutoff);
  build_vertex_triangles();
}

SurfaceIndex::SurfaceIndex(const PointCloud& cloud, double splat_radius, double spacing, double gather_radius,
                           double max_cutoff)
    : cloud_(&cloud), splat_radius_(splat_radius), cell_(gather_radius), point_reach_(max_cutoff + splat_radius) {
  if (!cloud.has_normals()) throw InputError("r-similarity of a point cloud needs a normal per point");
  element_normals_ = cloud.normals;
  std::vector<SurfacePoint> points;
  std::vector<std::uint32_t> kept;
  std::unordered_set<CellKey, CellKeyHash> taken;
  for (std::uint32_t i = 0; i < cloud.positions.size(); ++i)
    if (taken.insert(cell_key(cloud.positions[i], spacing)).second) {
      points.push_back({cloud.positions[i], cloud.normals[i]});
      kept.push_back(i);
    }
  set_samples(std::move(points), std::move(kept));
  // A disk within max_cutoff of a query has its centre within point_reach_ (>= the link distance).
  point_grid_ = std::make_unique<PointGrid>(cloud.positions, point_reach_);
}

SurfaceIndex::~SurfaceIndex() = default;

// Orders the samples by bucket and indexes the buckets.
void SurfaceIndex::set_samples(std::vector<SurfacePoint> points, std::vector<std::uint32_t> elements) {
  std::vector<Key> keys(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) keys[i] = key(points[i].position, cell_);
  std::vector<std::uint32_t> order(points.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t i, std::uint32_t j) { return keys[i] < keys[j]; });
  samples_.reserve(points.size());
  sample_elements_.reserve(points.size());
  for (std::uint32_t i : order) {
    samples_.push_back(points[i]);
    sample_elements_.push_back(elements[i]);
  }
  buckets_.assign(order.size(), [&](std::size_t i) { return keys[order[i]]; });
}

Vec3 SurfaceIndex::closest_on_element(std::uint32_t element, const Vec3& q) const {
  if (mesh_) {
    const auto [a, b, c] = mesh_->corners(element);
    return closest_point_on_triangle(q, a, b, c);
  }
  const Vec3& centre = cloud_->positions[element];
  const Vec3& n = element_normals_[element];
  Vec3 along = (q - centre) - (q - centre).dot(n) * n;
  const double length = along.norm();
  if (length > splat_radius_) along *= splat_radius_ / length;
  return centre + along;
}

void SurfaceIndex::build_vertex_triangles() {
  vertex_offsets_.assign(mesh_->positions.size() + 1, 0);
  for (const Triangle& t : mesh_->triangles)
    for (std::uint32_t v : t) ++vertex_offsets_[v + 1];
  std::partial_sum(vertex_offsets_.begin(), vertex_offsets_.end(), vertex_offsets_.begin());
  vertex_triangles_.resize(vertex_offsets_.back());
  std::vector<std::uint32_t> filled(vertex_offsets_.begin(), vertex_offsets_.end() - 1);
  for (std::uint32_t t = 0; t < mesh_->triangles.size(); ++t)
    for (std::uint32_t v : mesh_->triangles[t]) vertex_triangles_[filled[v]++] = t;
}

// Lists each triangle in every cell whose centre lies within max_cutoff + half the cell diagonal
// of it, so a query needs only the cell holding q. Cells are 2 x max_cutoff wide; candidates are
// visited column by column along the triangle's dominant normal axis, only near its plane.
void SurfaceIndex::build_triangle_grid(double max_cutoff) {
  const double g = triangle_cell_;
  const double reach = max_cutoff + 0.5 * std::sqrt(3.0) * g;
  constexpr std::size_t kChunk = 4096;
  const std::size_t triangles = mesh_->triangles.size(), chunks = (triangles + kChunk - 1) / kChunk;
  std::vector<std::vector<std::pair<Key, std::uint32_t>>> per_chunk(chunks);
  tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t chunk) {
    auto& items = per_chunk[chunk];
    const auto end = static_cast<std::uint32_t>(std::min(triangles, (chunk + 1) * kChunk));
    for (auto t = static_cast<std::uint32_t>(chunk * kChunk); t < end; ++t) {
      const auto [a, b, c] = mesh_->corners(t);
      const Vec3 n = element_normals_[t];
      const Vec3 lo = a.cwiseMin(b).cwiseMin(c).array() - reach, hi = a.cwiseMax(b).cwiseMax(c).array() + reach;
      int w = 0;
      n.cwiseAbs().maxCoeff(&w);
      const int u = (w + 1) % 3, v = (w + 2) % 3;
      auto index = [g](double x) { return static_cast<std::int64_t>(std::floor(x / g)); };
      for (std::int64_t i = index(lo[u]); i <= index(hi[u]); ++i)
        for (std::int64_t j = index(lo[v]); j <= index(hi[v]); ++j) {
          // Range of the plane's w over the column, widened by the reach along the normal.
          double w_lo = hi[w], w_hi = lo[w];
          for (int corner = 0; corner < 4; ++corner) {
            const double cu = static_cast<double>(i + (corner & 1)) * g, cv = static_cast<double>(j + (corner >> 1)) * g;
            const double plane_w = a[w] - (n[u] * (cu - a[u]) + n[v] * (cv - a[v])) / n[w];
            w_lo = std::min(w_lo, plane_w);
            w_hi = std::max(w_hi, plane_w);
          }
          const double slack = reach / std::abs(n[w]);
          for (std::int64_t k = index(std::max(lo[w], w_lo - slack)); k <= index(std::min(hi[w], w_hi + slack)); ++k) {
            Vec3 centre;
            centre[u] = (static_cast<double>(i) + 0.5) * g;
            centre[v] = (static_cast<double>(j) + 0.5) * g;
            centre[w] = (static_cast<double>(k) + 0.5) * g;
            if ((closest_point_on_triangle(centre, a, b, c) - centre).squaredNorm() <= reach * reach)
              items.emplace_back(key(centre, g), t);
          }
        }
    }
  });
  std::vector<std::pair<Key, std::uint32_t>> items;
  for (auto& chunk : per_chunk) {
    items.insert(items.end(), chunk.begin(), chunk.end());
    std::vector<std::pair<Key, std::uint32_t>>().swap(chunk);
  }
  tbb::parallel_sort(items.begin(), items.end());
  cell_triangles_.reserve(items.size());
  for (const auto& item : items) cell_triangles_.push_back(item.second);
  triangle_buckets_.assign(items.size(), [&](std::size_t i) { return items[i].first; });
}

SurfaceIndex::Key SurfaceIndex::key(const Vec3& p, double cell) {
  Key k = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const auto i = static_cast<std::int64_t>(std::floor(p[axis] / cell)) + kKeyBias;
    k = (k << 21) | (static_cast<Key>(std::clamp<std::int64_t>(i, 0, (1 << 21) - 1)));
  }
  return k;
}

void SurfaceIndex::gather(const Vec3& p, double radius, std::vector<std::uint32_t>& out) const {
  out.clear();
  const double radius2 = radius * radius;
  const Vec3 lo = (p.array() - radius) / cell_, hi = (p.array() + radius) / cell_;
  for (auto i = static_cast<std::int64_t>(std::floor(lo.x())); i <= static_cast<std::int64_t>(std::floor(hi.x())); ++i)
    for (auto j = static_cast<std::int64_t>(std::floor(lo.y())); j <= static_cast<std::int64_t>(std::floor(hi.y())); ++j)
      for (auto k = static_cast<std::int64_t>(std::floor(lo.z())); k <= static_cast<std::int64_t>(std::floor(hi.z())); ++k) {
        const Vec3 corner = (Vec3(static_cast<double>(i), static_cast<double>(j), static_cast<double>(k)).array() + 0.5) * cell_;
        const CellRanges::Range* found = buckets_.find(key(corner, cell_));
        if (!found) continue;
        for (std::uint32_t s = found->first; s < found->second; ++s)
          if ((samples_[s].position - p).squaredNorm() <= radius2) out.push_back(s);
      }
  std::sort(out.begin(), out.end());
}

bool SurfaceIndex::gather_connected(const Vec3& p, const Vec3& normal, double radius, double seed_cutoff, double min_cos,
                                    std::vector<std::uint32_t>& out, std::vector<std::uint32_t>* part) const {
  out.clear();
  if (part) part->clear();
  const std::optional<std::uint32_t> seed = closest_element(p, normal, seed_cutoff, min_cos);
  if (!seed) return false;
  std::vector<std::uint32_t> component{*seed};
  if (mesh_)
    connected_triangles(p, radius, component);
  else
    connected_points(p, radius, component);
  std::sort(component.begin(), component.end());
  gather(p, radius, out);
  out.erase(std::remove_if(out.begin(), out.end(),
                           [&](std::uint32_t s) { return !std::binary_search(component.begin(), component.end(), sample_elements_[s]); }),
            out.end());
  if (part) *part = std::move(component);
  return true;
}

// Floods from component[0] over triangles: across a vertex inside the ball to every triangle
// around it, across an edge that crosses the ball (both ends outside) to the triangles sharing it.
void SurfaceIndex::connected_triangles(const Vec3& p, double radius, std::vector<std::uint32_t>& component) const {
  const double radius2 = radius * radius;
  auto inside = [&](std::uint32_t v) { return (mesh_->positions[v] - p).squaredNorm() <= radius2; };
  auto segment_crosses = [&](std::uint32_t a, std::uint32_t b) {
    const Vec3 pa = mesh_->positions[a], ab = mesh_->positions[b] - pa;
    const double length2 = ab.squaredNorm();
    const double s = length2 > 0.0 ? std::clamp((p - pa).dot(ab) / length2, 0.0, 1.0) : 0.0;
    return (pa + s * ab - p).squaredNorm() <= radius2;
  };
  std::unordered_set<std::uint32_t> reached(component.begin(), component.end());
  for (std::size_t i = 0; i < component.size(); ++i) {
    const Triangle triangle = mesh_->triangles[component[i]];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = triangle[k], b = triangle[(k + 1) % 3];
      const bool a_inside = inside(a);
      if (!a_inside && (inside(b) || !segment_crosses(a, b))) continue;
      for (std::uint32_t j = vertex_offsets_[a]; j < vertex_offsets_[a + 1]; ++j) {
        const std::uint32_t u = vertex_triangles_[j];
        const Triangle& other = mesh_->triangles[u];
        const bool shares_edge = other[0] == b || other[1] == b || other[2] == b;
        if ((a_inside || shares_edge) && reached.insert(u).second) component.push_back(u);
      }
    }
  }
}

// Floods from component[0] over the cloud's points inside the ball, linking points closer than
// two splat radii (disks that overlap).
void SurfaceIndex::connected_points(const Vec3& p, double radius, std::vector<std::uint32_t>& component) const {
  const double radius2 = radius * radius;
  std::unordered_set<std::uint32_t> reached(component.begin(), component.end());
  for (std::size_t i = 0; i < component.size(); ++i)
    point_grid_->visit_within(cloud_->positions[component[i]], 2.0 * splat_radius_, [&](std::uint32_t other, double) {
      if ((cloud_->positions[other] - p).squaredNorm() <= radius2 && reached.insert(other).second) component.push_back(other);
    });
}

bool SurfaceIndex::near_any_of(const Vec3& q, double cutoff, const std::vector<std::uint32_t>& elements) const {
  const double cutoff2 = cutoff * cutoff;
  return visit_elements(q, [&](std::uint32_t t) {
    if (!std::binary_search(elements.begin(), elements.end(), t)) return false;
    return (closest_on_element(t, q) - q).squaredNorm() <= cutoff2;
  });
}

// Visits the elements that may pass within max_cutoff of q (a mesh: the triangles listed in q's
// cell; a cloud: the points within point_reach_), stopping when visit returns true.
template <class Visit>
bool SurfaceIndex::visit_elements(const Vec3& q, Visit&& visit) const {
  if (cloud_) return point_grid_->any_within(q, point_reach_, [&](std::uint32_t point, double) { return visit(point); });
  const CellRanges::Range* found = triangle_buckets_.find(key(q, triangle_cell_));
  if (!found) return false;
  for (std::uint32_t i = found->first; i < found->second; ++i)
    if (visit(cell_triangles_[i])) return true;
  return false;
}

bool SurfaceIndex::touches(const Vec3& q, const Vec3& normal, double tolerance, double min_cos) const {
  const double tolerance2 = tolerance * tolerance;
  return visit_elements(q, [&](std::uint32_t t) {
    if (!normals_agree(element_normals_[t], normal, min_cos)) return false;
    return (closest_on_element(t, q) - q).squaredNorm() <= tolerance2;
  });
}

std::optional<SurfacePoint> SurfaceIndex::closest(const Vec3& q, const Vec3& normal, double cutoff, double min_cos) const {
  const std::optional<std::uint32_t> t = closest_element(q, normal, cutoff, min_cos);
  if (!t) return std::nullopt;
  return SurfacePoint{closest_on_element(*t, q), element_normals_[*t]};
}

std::optional<std::uint32_t> SurfaceIndex::closest_element(const Vec3& q, const Vec3& normal, double cutoff,
                                                           double min_cos) const {
  std::optional<std::uint32_t> best;
  double best2 = cutoff * cutoff;
  visit_elements(q, [&](std::uint32_t t) {
    if (!normals_agree(element_normals_[t], normal, min_cos)) return false;
    const double d2 = (closest_on_element(t, q) - q).squaredNorm();
    if (d2 <= best2) {
      best2 = d2;
      best = t;
    }
    return false;
  });
  return best;
}

}  // namespace dg
