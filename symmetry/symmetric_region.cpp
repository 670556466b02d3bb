#include "symmetry/symmetric_region.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>

namespace dg {

CellTolerances cell_tolerances(const RegionOptions& options, bool point_cloud) {
  return point_cloud ? CellTolerances{options.cloud_angle_tolerance_degrees, options.cloud_offset_tolerance_eps}
                     : CellTolerances{options.angle_tolerance_degrees, options.offset_tolerance_eps};
}

CellMatcher::CellMatcher(const VoxelSurface& surface, const PointCloud* cloud, const RegionOptions& options)
    : surface_(surface),
      cos_tolerance_(std::cos(cell_tolerances(options, cloud != nullptr).angle_degrees * std::numbers::pi / 180.0)),
      offset_tolerance_(cell_tolerances(options, cloud != nullptr).offset_eps * surface.eps()),
      angle_tolerance_degrees_(options.angle_tolerance_degrees),
      max_bend_degrees_(options.max_bend_degrees),
      curved_deviation_(options.curved_deviation_eps * surface.eps()),
      half_diagonal_(0.5 * std::sqrt(3.0) * surface.eps()),
      cloud_(cloud) {}

bool CellMatcher::on_same_geometry(const Vec3& a, const Vec3& b, double distance, double bend_degrees) const {
  const double cos_angle = std::min(1.0, std::abs(a.dot(b)));
  if (cos_angle > cos_tolerance_ && distance < offset_tolerance_) return true;
  // Point-cloud planes are fitted, not tessellated: their bend is 0, so they stay exact too.
  if (bend_degrees <= angle_tolerance_degrees_) return false;
  const double allowed = std::min(angle_tolerance_degrees_ + bend_degrees, max_bend_degrees_) * std::numbers::pi / 180.0;
  if (cos_angle < std::cos(allowed)) return false;
  return distance + half_diagonal_ * std::sqrt(1.0 - cos_angle * cos_angle) < curved_deviation_;
}

std::int64_t nearest_cell(const VoxelSurface& surface, const Vec3& p) {
  const VoxelCoord v = surface.voxel_of(p);
  const std::int64_t direct = surface.find(v);
  if (direct >= 0) return direct;
  std::int64_t best = -1;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dz = -1; dz <= 1; ++dz) {
        const std::int64_t c = surface.find({v[0] + dx, v[1] + dy, v[2] + dz});
        if (c < 0) continue;
        const double d = (surface.centre(static_cast<std::uint32_t>(c)) - p).squaredNorm();
        if (d < best_distance) {
          best_distance = d;
          best = c;
        }
      }
  return best;
}

std::int64_t CellMatcher::image_cell(std::uint32_t cell, const RigidTransform& t) const {
  return nearest_cell(surface_, t.apply(surface_.centre(cell)));
}

std::size_t CellMatcher::image_of_cells(std::span<const std::uint32_t> cells, const RigidTransform& t,
                                        std::vector<char>& image) const {
  enum : char { outside = 0, inside = 1, tested_outside = 2 };
  image.assign(surface_.cell_count(), outside);
  std::vector<char> in_cells(surface_.cell_count(), 0);
  for (std::uint32_t c : cells) in_cells[c] = 1;
  const RigidTransform back = t.inverse();
  std::vector<std::uint32_t> rejected;  // tested cells whose centre maps back outside `cells`
  std::size_t off_surface = 0;
  for (std::uint32_t c : cells) {
    const Vec3 mapped = t.apply(surface_.centre(c));
    const std::int64_t hit = nearest_cell(surface_, mapped);
    if (hit < 0) {
      ++off_surface;
      continue;
    }
    image[static_cast<std::uint32_t>(hit)] = inside;
    const VoxelCoord v = surface_.voxel_of(mapped);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const std::int64_t found = surface_.find({v[0] + dx, v[1] + dy, v[2] + dz});
          if (found < 0 || image[static_cast<std::uint32_t>(found)] != outside) continue;
          const auto near = static_cast<std::uint32_t>(found);
          const std::int64_t source = image_cell(near, back);
          if (source >= 0 && in_cells[static_cast<std::uint32_t>(source)]) {
            image[near] = inside;
          } else {
            image[near] = tested_outside;
            rejected.push_back(near);
          }
        }
  }
  // A rejected cell may have become an image cell of a later centre: only the others go back.
  for (std::uint32_t c : rejected)
    if (image[c] == tested_outside) image[c] = outside;
  return off_surface;
}

namespace {

// The cells where mapped geometry may lie: first the voxel holding the image of the centre
// (where it almost always is), the whole 3x3x3 block around it only when something is missing.
class ImageCells {
 public:
  ImageCells(const VoxelSurface& surface, const VoxelCoord& voxel) : surface_(surface), voxel_(voxel) {
    const std::int64_t direct = surface.find(voxel);
    if (direct >= 0) cells_.push_back(static_cast<std::uint32_t>(direct));
    has_direct_ = direct >= 0;
  }

  // The voxel holding the image of the centre, when it is a surface cell.
  std::optional<std::uint32_t> direct() const {
    return has_direct_ ? std::optional<std::uint32_t>(cells_.front()) : std::nullopt;
  }

  // Calls `found(cell)` on the cells until it returns true; widens to the block once if needed.
  template <class Found>
  bool any(const Found& found) {
    for (std::uint32_t c : cells_)
      if (found(c)) return true;
    if (widened_) return false;
    widened_ = true;
    const std::size_t before = cells_.size();
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          if (dx == 0 && dy == 0 && dz == 0) continue;
          const std::int64_t c = surface_.find({voxel_[0] + dx, voxel_[1] + dy, voxel_[2] + dz});
          if (c >= 0) cells_.push_back(static_cast<std::uint32_t>(c));
        }
    for (std::size_t i = before; i < cells_.size(); ++i)
      if (found(cells_[i])) return true;
    return false;
  }

 private:
  const VoxelSurface& surface_;
  VoxelCoord voxel_;
  std::vector<std::uint32_t> cells_;
  bool has_direct_ = false;
  bool widened_ = false;
};

}  // namespace

bool CellMatcher::maps_onto_surface(std::uint32_t cell, const RigidTransform& t) const {
  const Vec3 centre = surface_.centre(cell);
  ImageCells image(surface_, surface_.voxel_of(t.apply(centre)));

  const std::span<const CellPlane> planes = surface_.planes(cell);
  // A scan's bent cells (creases, corners) fit their planes to few points each, and noise tilts
  // them: their mapped points decide instead, each near a plane of the image block.
  const std::span<const std::uint32_t> points = surface_.points(cell);
  if (cloud_ && planes.size() >= 2 && !points.empty()) {
    std::size_t near = 0;
    for (std::uint32_t p : points) {
      const Vec3 q = t.apply(cloud_->positions[p]);
      near += image.any([&](std::uint32_t other) {
        const std::span<const CellPlane> candidates = surface_.planes(other);
        return std::any_of(candidates.begin(), candidates.end(),
                           [&](const CellPlane& c) { return std::abs(c.normal.dot(q) - c.offset) < offset_tolerance_; });
      }) ? 1 : 0;
    }
    return 5 * near >= 4 * points.size();
  }
  for (const CellPlane& plane : planes) {
    const Vec3 source_foot = centre - (plane.normal.dot(centre) - plane.offset) * plane.normal;
    const Vec3 foot = t.apply(source_foot);
    const Vec3 normal = t.apply_direction(plane.normal);
    auto on_image_plane = [&](const CellPlane& candidate) {
      return on_same_geometry(candidate.normal, normal, std::abs(candidate.normal.dot(foot) - candidate.offset),
                              std::max(plane.bend_degrees, candidate.bend_degrees));
    };
    auto of_its_material = [&](const CellPlane& candidate) {
      return candidate.material == plane.material && on_image_plane(candidate);
    };
    if (const std::optional<std::uint32_t> direct = image.direct()) {
      const std::span<const CellPlane> direct_planes = surface_.planes(*direct);
      if (std::any_of(direct_planes.begin(), direct_planes.end(), of_its_material)) continue;
      // The image voxel may hold the plane in other materials only (never without materials, where
      // all are 0). Then a cell with one material on this plane lies inside a painted area, not on
      // its border, and that voxel decides alone: a neighbour of the right colour may not stand in
      // for it (else a strip three voxels wide would match its shifted copy).
      auto inside_one_material = [&] {
        return std::none_of(planes.begin(), planes.end(), [&](const CellPlane& other) {
          return other.material != plane.material &&
                 on_same_geometry(other.normal, plane.normal, std::abs(other.normal.dot(source_foot) - other.offset),
                                  std::max(plane.bend_degrees, other.bend_degrees));
        });
      };
      if (std::any_of(direct_planes.begin(), direct_planes.end(), on_image_plane) && inside_one_material()) return false;
    }
    const bool found = image.any([&](std::uint32_t other) {
      const std::span<const CellPlane> candidates = surface_.planes(other);
      return std::any_of(candidates.begin(), candidates.end(), of_its_material);
    });
    if (!found) return false;
  }
  for (const CellLine& line : surface_.lines(cell)) {
    const Vec3 foot = t.apply(line.point + (centre - line.point).dot(line.direction) * line.direction);
    const Vec3 direction = t.apply_direction(line.direction);
    const bool found = image.any([&](std::uint32_t other) {
      for (const CellLine& candidate : surface_.lines(other)) {
        if (candidate.kind != line.kind) continue;
        const Vec3 offset = foot - candidate.point;
        if (on_same_geometry(candidate.direction, direction, (offset - offset.dot(candidate.direction) * candidate.direction).norm(),
                             std::max(line.bend_degrees, candidate.bend_degrees)))
          return true;
      }
      return false;
    });
    if (!found) return false;
  }
  return true;
}

bool CellMatcher::symmetric(std::uint32_t cell, const RigidTransform& t, const RigidTransform& inverse) const {
  if (!maps_onto_surface(cell, t)) return false;
  const std::int64_t image = image_cell(cell, t);
  return image >= 0 && maps_onto_surface(static_cast<std::uint32_t>(image), inverse);
}

SurfaceParts surface_parts(const VoxelSurface& surface) {
  constexpr std::size_t kSamples = 8;
  SurfaceParts parts;
  std::size_t count = 0;
  parts.part_of = surface.components(&count);
  std::vector<std::size_t> size(count, 0), seen(count, 0);
  for (std::uint32_t part : parts.part_of) ++size[part];
  parts.samples.resize(count);
  // Cells are numbered in order of their voxel coordinates: every stride-th cell of a part lies
  // spread across it.
  for (std::uint32_t c = 0; c < parts.part_of.size(); ++c) {
    const std::uint32_t part = parts.part_of[c];
    if (seen[part]++ % std::max<std::size_t>(1, size[part] / kSamples) == 0) parts.samples[part].push_back(c);
  }
  return parts;
}

SymmetricRegion symmetric_region(const CellMatcher& matcher, const VoxelSurface& surface, const RigidTransform& t,
                                 std::span<const std::uint32_t> seeds, bool fill_outliers, const SurfaceParts* parts) {
  SymmetricRegion region;
  const RigidTransform inverse = t.inverse();
  enum : std::uint8_t { unknown, yes, no };
  std::vector<std::uint8_t> state(surface.cell_count(), unknown);
  std::vector<std::uint32_t> queue, tested;
  auto test = [&](std::uint32_t c) {
    if (state[c] != unknown) return;
    ++region.cells_tested;
    if (parts) tested.push_back(c);
    state[c] = matcher.symmetric(c, t, inverse) ? yes : no;
    if (state[c] == yes) queue.push_back(c);
  };
  for (std::uint32_t s : seeds) test(s);
  // A noisy cloud's seeds (corner cells and their neighbours) pass less often: about a fifth of
  // them for the facade's pitches under noise of 0.075 eps, up to one in fifteen for wrong motions.
  const std::size_t min_share = fill_outliers ? 10 : 4;
  if (min_share * queue.size() < seeds.size() || queue.empty()) {
    region.rejected_early = true;
    return region;
  }
  for (std::size_t head = 0; head < queue.size(); ++head)
    for (std::uint32_t n : surface.neighbours(queue[head])) test(n);
  // Parts that no seed reached (a table's top beside the chairs that hold the seeds): their
  // sample cells are tested, and when most pass, the region grows from them. A part only a patch
  // of which maps onto the model (a box's flat face under a half turn about a line in that face)
  // stays out: such patches are chance, not a repeat of the part.
  if (parts) {
    std::vector<char> reached(parts->samples.size(), 0);
    for (std::uint32_t c : tested) reached[parts->part_of[c]] = 1;
    for (std::size_t p = 0; p < parts->samples.size(); ++p) {
      if (reached[p]) continue;
      const std::size_t grown = queue.size();
      for (std::uint32_t c : parts->samples[p]) test(c);
      if (2 * (queue.size() - grown) < parts->samples[p].size()) {
        for (std::size_t k = grown; k < queue.size(); ++k) state[queue[k]] = no;
        queue.resize(grown);
        continue;
      }
      for (std::size_t head = grown; head < queue.size(); ++head)
        for (std::uint32_t n : surface.neighbours(queue[head])) test(n);
    }
  }

  if (fill_outliers) {
    std::vector<std::uint32_t> filled;
    for (std::uint32_t c = 0; c < surface.cell_count(); ++c) {
      if (state[c] != no) continue;
      std::size_t symmetric_neighbours = 0;
      const auto neighbours = surface.neighbours(c);
      for (std::uint32_t n : neighbours) symmetric_neighbours += state[n] == yes ? 1 : 0;
      if (!neighbours.empty() && 4 * symmetric_neighbours >= 3 * neighbours.size()) filled.push_back(c);
    }
    for (std::uint32_t c : filled) {
      state[c] = yes;
      queue.push_back(c);
    }
    // Small clusters of failed (or, enclosed by them, untested) cells with symmetric cells all
    // around: scan noise too, at most the cells of a disk of diameter r.
    const double radius_cells = 0.5 * surface.r() / surface.eps();
    const auto max_cluster = static_cast<std::size_t>(std::ceil(std::numbers::pi * radius_cells * radius_cells));
    enum : std::uint8_t { open, in_cluster, large };  // a large cluster's cells stop later searches
    std::vector<std::uint8_t> visited(surface.cell_count(), open);
    std::vector<std::uint32_t> cluster;
    for (std::uint32_t c = 0; c < surface.cell_count(); ++c) {
      if (state[c] != no || visited[c] != open) continue;
      cluster.assign(1, c);
      visited[c] = in_cluster;
      bool too_large = false;
      for (std::size_t head = 0; head < cluster.size() && !too_large && cluster.size() <= max_cluster; ++head)
        for (std::uint32_t n : surface.neighbours(cluster[head])) {
          if (state[n] == yes) continue;
          if (visited[n] == large) too_large = true;
          if (visited[n] != open) continue;
          visited[n] = in_cluster;
          cluster.push_back(n);
        }
      too_large = too_large || cluster.size() > max_cluster;
      if (too_large) {
        for (std::uint32_t k : cluster) visited[k] = large;
        continue;
      }
      for (std::uint32_t k : cluster) {
        state[k] = yes;
        queue.push_back(k);
      }
    }
  }
  std::sort(queue.begin(), queue.end());
  region.symmetric_cells = std::move(queue);
  for (std::uint32_t c : region.symmetric_cells) region.symmetric_area += surface.area(c);
  region.r_symmetric_cells = erode(surface, region.symmetric_cells, surface.r());
  for (std::uint32_t c : region.r_symmetric_cells) region.r_symmetric_area += surface.area(c);
  return region;
}

SymmetricRegion tested_symmetric_region(const CellMatcher& matcher, const VoxelSurface& surface, const RigidTransform& t) {
  const RigidTransform inverse = t.inverse();
  std::vector<char> symmetric(surface.cell_count(), 0);
  tbb::parallel_for(std::uint32_t{0}, static_cast<std::uint32_t>(surface.cell_count()),
                    [&](std::uint32_t c) { symmetric[c] = matcher.symmetric(c, t, inverse) ? 1 : 0; });
  SymmetricRegion region;
  for (std::uint32_t c = 0; c < surface.cell_count(); ++c)
    if (symmetric[c]) {
      region.symmetric_cells.push_back(c);
      region.symmetric_area += surface.area(c);
    }
  region.r_symmetric_cells = erode(surface, region.symmetric_cells, surface.r());
  for (std::uint32_t c : region.r_symmetric_cells) region.r_symmetric_area += surface.area(c);
  region.cells_tested = surface.cell_count();
  return region;
}

std::vector<std::uint32_t> erode(const VoxelSurface& surface, const std::vector<std::uint32_t>& region, double r) {
  // Distances from the cells just outside the region, travelling through region cells only.
  std::vector<char> inside(surface.cell_count(), 0);
  for (std::uint32_t c : region) inside[c] = 1;
  std::vector<std::uint32_t> border;
  for (std::uint32_t c : region)
    for (std::uint32_t n : surface.neighbours(c))
      if (!inside[n]) border.push_back(n);
  std::sort(border.begin(), border.end());
  border.erase(std::unique(border.begin(), border.end()), border.end());
  const std::vector<double> distance = surface.intrinsic_distance(border, r, &inside);
  std::vector<std::uint32_t> eroded;
  for (std::uint32_t c : region)
    if (distance[c] > r) eroded.push_back(c);
  return eroded;
}

}  // namespace dg
