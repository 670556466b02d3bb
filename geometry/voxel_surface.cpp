#include "geometry/voxel_surface.h"

#include "geometry/box_overlap.h"
#include "geometry/cloud_cell_geometry.h"
#include "geometry/clip_polygon.h"
#include "geometry/errors.h"
#include "geometry/tessellation_bend.h"

#include <fmt/format.h>
#include <openvdb/openvdb.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <numbers>
#include <optional>
#include <string>

namespace dg {

struct VoxelSurface::Grid {
  openvdb::Int32Grid::Ptr index;  // voxel -> cell index, background -1, never changed once built
  std::uint64_t id = next_grid_id();  // unique in the process: names the grid for cached lookups

  static std::uint64_t next_grid_id() {
    static std::atomic<std::uint64_t> next{1};
    return next++;
  }
};

VoxelSurface::VoxelSurface() = default;
VoxelSurface::~VoxelSurface() = default;
VoxelSurface::VoxelSurface(VoxelSurface&&) noexcept = default;
VoxelSurface& VoxelSurface::operator=(VoxelSurface&&) noexcept = default;

double default_radius(const BoundingBox& bounds) { return 0.016 * bounds.longest_side(); }

namespace {

constexpr std::int32_t kKeyBias = 1 << 20;  // voxel coordinates must lie in (-2^20, 2^20)
constexpr std::size_t kChunk = 2048;         // triangles per parallel work item (fixed: determinism)

using VoxelKey = std::uint64_t;
using KeyedItem = std::pair<VoxelKey, std::uint32_t>;

VoxelKey pack(std::int64_t i, std::int64_t j, std::int64_t k) {
  return (static_cast<VoxelKey>(i + kKeyBias) << 42) | (static_cast<VoxelKey>(j + kKeyBias) << 21) |
         static_cast<VoxelKey>(k + kKeyBias);
}

VoxelCoord unpack(VoxelKey key) {
  const VoxelKey mask = (VoxelKey(1) << 21) - 1;
  return {static_cast<std::int32_t>((key >> 42) & mask) - kKeyBias,
          static_cast<std::int32_t>((key >> 21) & mask) - kKeyBias, static_cast<std::int32_t>(key & mask) - kKeyBias};
}

// Voxel index range [first, last] of closed voxels that can touch the interval [lo, hi]
// (a small slack absorbs the rounding of the division; the exact test decides later).
std::pair<std::int64_t, std::int64_t> voxel_range(double lo, double hi, double eps) {
  return {static_cast<std::int64_t>(std::ceil(lo / eps - 1e-9)) - 1, static_cast<std::int64_t>(std::floor(hi / eps + 1e-9))};
}

// Appends (voxel key, id) for every closed voxel the triangle (a, b, c) touches. A segment is
// passed as (a, b, b).
void voxelize(const Vec3& a, const Vec3& b, const Vec3& c, double eps, std::uint32_t id, std::vector<KeyedItem>& out) {
  const ClipPolygon triangle = ClipPolygon::triangle(a, b, c);
  const double slack = 1e-7 * eps;
  const auto [x_lo, x_hi] = triangle.range(0);
  const auto [i_first, i_last] = voxel_range(x_lo, x_hi, eps);
  for (std::int64_t i = i_first; i <= i_last; ++i) {
    const double x0 = static_cast<double>(i) * eps, x1 = static_cast<double>(i + 1) * eps;
    const ClipPolygon in_x = triangle.slab(0, x0 - slack, x1 + slack);
    if (in_x.size == 0) continue;
    const auto [y_lo, y_hi] = in_x.range(1);
    const auto [j_first, j_last] = voxel_range(y_lo, y_hi, eps);
    for (std::int64_t j = j_first; j <= j_last; ++j) {
      const double y0 = static_cast<double>(j) * eps, y1 = static_cast<double>(j + 1) * eps;
      const ClipPolygon in_xy = in_x.slab(1, y0 - slack, y1 + slack);
      if (in_xy.size == 0) continue;
      const auto [z_lo, z_hi] = in_xy.range(2);
      const auto [k_first, k_last] = voxel_range(z_lo, z_hi, eps);
      for (std::int64_t k = k_first; k <= k_last; ++k) {
        const Vec3 lo(x0, y0, static_cast<double>(k) * eps);
        const Vec3 hi(x1, y1, static_cast<double>(k + 1) * eps);
        if (triangle_box_overlap(a, b, c, lo, hi)) out.emplace_back(pack(i, j, k), id);
      }
    }
  }
}

// Runs `emit(item, out)` over items in fixed chunks in parallel and returns all pairs sorted.
template <class Emit>
std::vector<KeyedItem> collect_sorted(std::size_t item_count, const Emit& emit) {
  const std::size_t chunks = (item_count + kChunk - 1) / kChunk;
  std::vector<std::vector<KeyedItem>> per_chunk(chunks);
  tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t chunk) {
    const std::size_t end = std::min(item_count, (chunk + 1) * kChunk);
    for (std::size_t item = chunk * kChunk; item < end; ++item) emit(static_cast<std::uint32_t>(item), per_chunk[chunk]);
  });
  std::size_t total = 0;
  for (const auto& v : per_chunk) total += v.size();
  std::vector<KeyedItem> all;
  all.reserve(total);
  for (auto& v : per_chunk) {
    all.insert(all.end(), v.begin(), v.end());
    std::vector<KeyedItem>().swap(v);
  }
  tbb::parallel_sort(all.begin(), all.end());
  return all;
}

// Fills a CSR table from items sorted by key: offsets per cell of `keys` (sorted unique) and
// the ids. Items whose key is not a cell are skipped.
void fill_csr(const std::vector<VoxelKey>& keys, const std::vector<KeyedItem>& items, std::vector<std::uint32_t>& offsets,
              std::vector<std::uint32_t>& ids) {
  offsets.assign(keys.size() + 1, 0);
  ids.clear();
  ids.reserve(items.size());
  std::size_t cell = 0;
  for (const KeyedItem& item : items) {
    while (cell < keys.size() && keys[cell] < item.first) offsets[++cell] = static_cast<std::uint32_t>(ids.size());
    if (cell == keys.size()) break;
    if (keys[cell] == item.first) ids.push_back(item.second);
  }
  while (cell < keys.size()) offsets[++cell] = static_cast<std::uint32_t>(ids.size());
}

// Builds a CSR array of per-cell records by running `make(cell, out)` twice (count, then fill)
// in parallel.
template <class T, class Make>
void build_records(std::size_t cells, std::vector<std::uint32_t>& offsets, std::vector<T>& records, const Make& make) {
  std::vector<std::uint32_t> counts(cells + 1, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cells, 4096), [&](const tbb::blocked_range<std::size_t>& range) {
    std::vector<T> scratch;
    for (std::size_t c = range.begin(); c != range.end(); ++c) {
      scratch.clear();
      make(static_cast<std::uint32_t>(c), scratch);
      counts[c + 1] = static_cast<std::uint32_t>(scratch.size());
    }
  });
  for (std::size_t c = 0; c < cells; ++c) counts[c + 1] += counts[c];
  records.resize(counts.back());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cells, 4096), [&](const tbb::blocked_range<std::size_t>& range) {
    std::vector<T> scratch;
    for (std::size_t c = range.begin(); c != range.end(); ++c) {
      scratch.clear();
      make(static_cast<std::uint32_t>(c), scratch);
      std::copy(scratch.begin(), scratch.end(), records.begin() + counts[c]);
    }
  });
  offsets = std::move(counts);
}

}  // namespace

bool within_voxel_reach(const BoundingBox& bounds, double eps) {
  const double limit = static_cast<double>(kKeyBias - 2);
  for (int axis = 0; axis < 3; ++axis)
    if (!(std::abs(bounds.min[axis] / eps) <= limit && std::abs(bounds.max[axis] / eps) <= limit)) return false;
  return true;
}

// Friend of VoxelSurface: fills its private arrays.
class VoxelSurfaceBuilder {
 public:
  VoxelSurfaceBuilder(const BoundingBox& bounds, const VoxelSurfaceOptions& options) {
    if (bounds.empty()) throw InputError("empty model: nothing to voxelize");
    surface_.r_ = options.r > 0.0 ? options.r : default_radius(bounds);
    if (!(surface_.r_ > 0.0) || !std::isfinite(surface_.r_))
      throw InputError("model has zero extent: cannot choose a radius (pass -r)");
    surface_.eps_ = options.eps > 0.0 ? options.eps : surface_.r_ / 4.0;
    if (surface_.eps_ > surface_.r_)
      throw InputError(fmt::format("voxel size {:.6g} is larger than the radius r = {:.6g}: a voxel must fit inside the "
                                   "r-neighbourhood (default voxel size r/4)",
                                   surface_.eps_, surface_.r_));
    if (!within_voxel_reach(bounds, surface_.eps_))
      throw InputError("voxel size " + std::to_string(surface_.eps_) +
                       " is too small for the model's coordinates (more than 2^20 voxels from the origin); "
                       "pass a larger -r or --voxel");
  }

  VoxelSurface& surface() { return surface_; }

  // Creates cells for the sorted unique keys and the OpenVDB index grid.
  void set_cells(std::vector<VoxelKey> keys) {
    keys_ = std::move(keys);
    surface_.coords_.resize(keys_.size());
    tbb::parallel_for(std::size_t(0), keys_.size(), [&](std::size_t c) { surface_.coords_[c] = unpack(keys_[c]); });
    openvdb::initialize();
    // Looked up by voxel coordinate only, so the grid keeps the identity transform: OpenVDB
    // refuses a voxel-size transform below about 1.4e-5 (eps^3 under its scale tolerance), which
    // models a few millimetres across in metres need.
    auto grid = openvdb::Int32Grid::create(-1);
    grid->setName("cell_index");
    auto accessor = grid->getAccessor();
    for (std::size_t c = 0; c < keys_.size(); ++c) {
      const VoxelCoord& v = surface_.coords_[c];
      accessor.setValueOn(openvdb::Coord(v[0], v[1], v[2]), static_cast<std::int32_t>(c));
    }
    surface_.grid_ = std::make_unique<VoxelSurface::Grid>();
    surface_.grid_->index = grid;
  }

  const std::vector<VoxelKey>& keys() const { return keys_; }

  void set_triangles(const std::vector<KeyedItem>& items) {
    fill_csr(keys_, items, surface_.triangle_offsets_, surface_.triangles_);
  }
  void set_points(const std::vector<KeyedItem>& items) { fill_csr(keys_, items, surface_.point_offsets_, surface_.points_); }

  template <class Make>
  void set_planes(const Make& make) {
    build_records(keys_.size(), surface_.plane_offsets_, surface_.planes_, make);
  }
  template <class Make>
  void set_lines(const Make& make) {
    build_records(keys_.size(), surface_.line_offsets_, surface_.lines_, make);
  }

  // Cell areas from a per-cell function; the total is summed in cell order (deterministic).
  template <class Area>
  void set_areas(const Area& area) {
    surface_.areas_.assign(keys_.size(), 0.0);
    tbb::parallel_for(std::size_t(0), keys_.size(), [&](std::size_t c) { surface_.areas_[c] = area(static_cast<std::uint32_t>(c)); });
    surface_.total_area_ = 0.0;
    for (double a : surface_.areas_) surface_.total_area_ += a;
  }

  void set_neighbours() {
    build_records(keys_.size(), surface_.neighbour_offsets_, surface_.neighbours_,
                  [&](std::uint32_t c, std::vector<std::uint32_t>& out) {
                    const VoxelCoord& v = surface_.coords_[c];
                    for (int dx = -1; dx <= 1; ++dx)
                      for (int dy = -1; dy <= 1; ++dy)
                        for (int dz = -1; dz <= 1; ++dz) {
                          if (dx == 0 && dy == 0 && dz == 0) continue;
                          const std::int64_t n = surface_.find({v[0] + dx, v[1] + dy, v[2] + dz});
                          if (n >= 0) out.push_back(static_cast<std::uint32_t>(n));
                        }
                    std::sort(out.begin(), out.end());
                  });
  }

 private:
  VoxelSurface surface_;
  std::vector<VoxelKey> keys_;
};

namespace {

std::vector<VoxelKey> unique_keys(const std::vector<KeyedItem>& items) {
  std::vector<VoxelKey> keys;
  keys.reserve(items.size() / 2 + 1);
  for (const KeyedItem& item : items)
    if (keys.empty() || keys.back() != item.first) keys.push_back(item.first);
  return keys;
}

struct WeightedPlane {
  CellPlane plane;
  double weight = 0.0;  // area of the triangle it came from; 0 = degenerate
};

// Merges planes of one material equal within tolerance; keeps the representative of the largest triangle.
void merge_planes(std::span<const std::uint32_t> triangles, const std::vector<WeightedPlane>& triangle_planes,
                  double cos_tolerance, double offset_tolerance, std::vector<CellPlane>& out) {
  std::vector<double> weights;
  for (std::uint32_t t : triangles) {
    const WeightedPlane& p = triangle_planes[t];
    if (p.weight <= 0.0) continue;
    bool merged = false;
    for (std::size_t m = 0; m < out.size(); ++m) {
      if (out[m].material == p.plane.material && out[m].normal.dot(p.plane.normal) > cos_tolerance &&
          std::abs(out[m].offset - p.plane.offset) < offset_tolerance) {
        const double bend = std::max(out[m].bend_degrees, p.plane.bend_degrees);
        if (p.weight > weights[m]) {
          out[m] = p.plane;
          weights[m] = p.weight;
        }
        out[m].bend_degrees = bend;
        merged = true;
        break;
      }
    }
    if (!merged) {
      out.push_back(p.plane);
      weights.push_back(p.weight);
    }
  }
}

}  // namespace

VoxelSurface build_voxel_surface(const TriangleMesh& mesh, const std::vector<FeatureEdge>& features,
                                 const VoxelSurfaceOptions& options, const ProgressCallback& progress) {
  if (mesh.triangles.empty()) throw InputError("empty model: the mesh has no triangles");
  VoxelSurfaceBuilder builder(mesh.bounds(), options);
  const double eps = builder.surface().eps();

  report_progress(progress, "voxelize triangles", 0.0);
  const std::vector<KeyedItem> triangle_items = collect_sorted(mesh.triangles.size(), [&](std::uint32_t t, auto& out) {
    const auto [a, b, c] = mesh.corners(t);
    voxelize(a, b, c, eps, t, out);
  });
  builder.set_cells(unique_keys(triangle_items));
  builder.set_triangles(triangle_items);

  report_progress(progress, "cell planes", 0.4);
  const std::vector<double> bends = triangle_bend_degrees(mesh, features);
  std::vector<WeightedPlane> triangle_planes(mesh.triangles.size());
  tbb::parallel_for(std::size_t(0), mesh.triangles.size(), [&](std::size_t t) {
    const Vec3 n = mesh.area_vector(t);
    const double length = n.norm();
    if (length <= 0.0) return;
    const Vec3 unit = n / length;
    const std::uint32_t material =
        !options.material_classes.empty() && mesh.has_materials() ? options.material_classes[mesh.materials[t]] : 0;
    triangle_planes[t] = {{unit, unit.dot(mesh.positions[mesh.triangles[t][0]]), material, bends[t]}, 0.5 * length};
  });
  const double cos_tolerance = std::cos(options.plane_merge_angle_degrees * std::numbers::pi / 180.0);
  const double offset_tolerance = options.plane_merge_offset * eps;
  VoxelSurface& surface = builder.surface();
  builder.set_planes([&](std::uint32_t cell, std::vector<CellPlane>& out) {
    merge_planes(surface.triangles(cell), triangle_planes, cos_tolerance, offset_tolerance, out);
  });

  builder.set_areas([&](std::uint32_t cell) {
    const Vec3 lo = eps * Vec3(surface.coord(cell)[0], surface.coord(cell)[1], surface.coord(cell)[2]);
    const Vec3 hi = lo + Vec3::Constant(eps);
    double sum = 0.0;
    for (std::uint32_t t : surface.triangles(cell)) {
      const auto [a, b, c] = mesh.corners(t);
      const ClipPolygon piece = ClipPolygon::triangle(a, b, c).box(lo, hi);
      if (piece.size >= 3) sum += piece.area();
    }
    return sum;
  });

  report_progress(progress, "cell lines", 0.6);
  const std::vector<KeyedItem> edge_items = collect_sorted(features.size(), [&](std::uint32_t e, auto& out) {
    const Vec3& a = mesh.positions[features[e].v0];
    const Vec3& b = mesh.positions[features[e].v1];
    if (a != b) voxelize(a, b, b, eps, e, out);
  });
  const std::vector<double> edge_bends = feature_edge_bend_degrees(mesh, features, options.corner_angle_degrees);
  std::vector<std::uint32_t> edge_offsets, edge_ids;
  fill_csr(builder.keys(), edge_items, edge_offsets, edge_ids);
  builder.set_lines([&](std::uint32_t cell, std::vector<CellLine>& out) {
    const Vec3 centre = surface.centre(cell);
    for (std::uint32_t n = edge_offsets[cell]; n < edge_offsets[cell + 1]; ++n) {
      const FeatureEdge& edge = features[edge_ids[n]];
      const double bend = edge_bends[edge_ids[n]];
      const Vec3& a = mesh.positions[edge.v0];
      const Vec3 direction = (mesh.positions[edge.v1] - a).normalized();
      const Vec3 point = a + (centre - a).dot(direction) * direction;  // closest to the cell centre
      bool merged = false;
      for (CellLine& line : out) {
        const Vec3 offset = point - line.point;
        if (std::abs(line.direction.dot(direction)) > cos_tolerance &&
            (offset - offset.dot(line.direction) * line.direction).norm() < offset_tolerance && line.kind == edge.kind) {
          line.bend_degrees = std::max(line.bend_degrees, bend);
          merged = true;
          break;
        }
      }
      if (!merged) out.push_back({point, direction, edge.kind, bend});
    }
  });

  report_progress(progress, "neighbourhoods", 0.8);
  builder.set_neighbours();
  report_progress(progress, "voxel surface", 1.0);
  return std::move(builder.surface());
}

VoxelSurface build_voxel_surface(const PointCloud& cloud, const VoxelSurfaceOptions& options,
                                 const ProgressCallback& progress) {
  if (cloud.positions.empty()) throw InputError("empty model: the point cloud has no points");
  VoxelSurfaceBuilder builder(cloud.bounds(), options);
  const double eps = builder.surface().eps();
  report_progress(progress, "voxelize points", 0.0);
  std::vector<KeyedItem> items(cloud.positions.size());
  tbb::parallel_for(std::size_t(0), cloud.positions.size(), [&](std::size_t p) {
    const Vec3& x = cloud.positions[p];
    items[p] = {pack(static_cast<std::int64_t>(std::floor(x.x() / eps)), static_cast<std::int64_t>(std::floor(x.y() / eps)),
                     static_cast<std::int64_t>(std::floor(x.z() / eps))),
                static_cast<std::uint32_t>(p)};
  });
  tbb::parallel_sort(items.begin(), items.end());
  builder.set_cells(unique_keys(items));
  builder.set_points(items);
  // A surface through a voxel covers about eps^2; points spread that over the cells by density.
  const double area_per_point =
      eps * eps * static_cast<double>(builder.keys().size()) / static_cast<double>(cloud.positions.size());
  builder.set_areas([&](std::uint32_t cell) { return area_per_point * static_cast<double>(builder.surface().points(cell).size()); });
  report_progress(progress, "neighbourhoods", 0.5);
  builder.set_neighbours();
  report_progress(progress, "cell planes", 0.7);
  const std::vector<CloudCell> fitted = fit_cloud_cells(cloud, builder.surface());
  builder.set_planes([&](std::uint32_t cell, std::vector<CellPlane>& out) { out = fitted[cell].planes; });
  builder.set_lines([&](std::uint32_t cell, std::vector<CellLine>& out) { out = fitted[cell].lines; });
  report_progress(progress, "voxel surface", 1.0);
  return std::move(builder.surface());
}

Vec3 VoxelSurface::centre(std::uint32_t cell) const {
  const VoxelCoord& v = coords_[cell];
  return eps_ * Vec3(v[0] + 0.5, v[1] + 0.5, v[2] + 0.5);
}

VoxelCoord VoxelSurface::voxel_of(const Vec3& p) const {
  return {static_cast<std::int32_t>(std::floor(p.x() / eps_)), static_cast<std::int32_t>(std::floor(p.y() / eps_)),
          static_cast<std::int32_t>(std::floor(p.z() / eps_))};
}

std::int64_t VoxelSurface::find(const VoxelCoord& voxel) const {
  if (!grid_) return -1;
  // Each thread keeps an accessor to the grid it looked in last: it caches the tree nodes of the
  // previous lookup, so a lookup next to it (most are) skips the descent from the root. The
  // accessor is not registered with the tree (cheap to make; the grid never changes) and is
  // replaced when another grid is asked, known by its id (never reused, unlike an address).
  using Accessor = openvdb::tree::ValueAccessor<const openvdb::Int32Tree, /*IsSafe=*/false>;
  thread_local std::uint64_t accessor_grid = 0;
  thread_local std::optional<Accessor> accessor;
  if (accessor_grid != grid_->id) {
    accessor.emplace(grid_->index->constTree());
    accessor_grid = grid_->id;
  }
  return accessor->getValue(openvdb::Coord(voxel[0], voxel[1], voxel[2]));
}

std::vector<std::uint32_t> VoxelSurface::components(std::size_t* component_count) const {
  constexpr std::uint32_t unset = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> label(cell_count(), unset);
  std::vector<std::uint32_t> stack;
  std::uint32_t next = 0;
  for (std::uint32_t seed = 0; seed < cell_count(); ++seed) {
    if (label[seed] != unset) continue;
    label[seed] = next;
    stack.push_back(seed);
    while (!stack.empty()) {
      const std::uint32_t c = stack.back();
      stack.pop_back();
      for (std::uint32_t n : neighbours(c))
        if (label[n] == unset) {
          label[n] = next;
          stack.push_back(n);
        }
    }
    ++next;
  }
  if (component_count) *component_count = next;
  return label;
}

std::vector<double> VoxelSurface::intrinsic_distance(std::span<const std::uint32_t> sources, double max_distance,
                                                     const std::vector<char>* passable) const {
  std::vector<double> distance(cell_count(), std::numeric_limits<double>::infinity());
  // Dial's bucket queue: bucket k holds the cells reached at a distance in [k eps, (k + 1) eps).
  // Every step is at least eps long, so a cell taken from bucket k only lowers cells of later
  // buckets, and the buckets are settled in order like a heap's front (a step that rounding
  // leaves in the current bucket goes to its end). Entries whose distance has dropped since are
  // skipped.
  using Entry = std::pair<double, std::uint32_t>;
  std::vector<std::vector<Entry>> buckets(1);
  auto bucket_of = [&](double d) { return static_cast<std::size_t>(d / eps_); };
  for (std::uint32_t s : sources) {
    distance[s] = 0.0;
    buckets[0].emplace_back(0.0, s);
  }
  const double step[4] = {0.0, eps_, std::sqrt(2.0) * eps_, std::sqrt(3.0) * eps_};
  for (std::size_t k = 0; k < buckets.size(); ++k)
    for (std::size_t i = 0; i < buckets[k].size(); ++i) {
      const auto [d, c] = buckets[k][i];
      if (d > distance[c]) continue;
      const VoxelCoord& vc = coords_[c];
      for (std::uint32_t n : neighbours(c)) {
        if (passable && !(*passable)[n]) continue;
        const VoxelCoord& vn = coords_[n];
        const int axes_changed = (vn[0] != vc[0]) + (vn[1] != vc[1]) + (vn[2] != vc[2]);
        const double candidate = d + step[axes_changed];
        if (candidate < distance[n] && candidate <= max_distance) {
          distance[n] = candidate;
          const std::size_t b = std::max(k, bucket_of(candidate));
          if (b >= buckets.size()) buckets.resize(b + 1);
          buckets[b].emplace_back(candidate, n);
        }
      }
    }
  return distance;
}

VoxelSurfaceStats VoxelSurface::stats() const {
  VoxelSurfaceStats s;
  s.voxels = cell_count();
  s.planes = planes_.size();
  s.lines = lines_.size();
  s.points = points_.size();
  s.memory_bytes = coords_.capacity() * sizeof(VoxelCoord) + planes_.capacity() * sizeof(CellPlane) +
                   lines_.capacity() * sizeof(CellLine) +
                   (triangles_.capacity() + points_.capacity() + neighbours_.capacity() + plane_offsets_.capacity() +
                    line_offsets_.capacity() + triangle_offsets_.capacity() + point_offsets_.capacity() +
                    neighbour_offsets_.capacity()) *
                       sizeof(std::uint32_t) +
                   (grid_ ? grid_->index->memUsage() : 0);
  return s;
}

}  // namespace dg
