#include "grammar/docking_sites.h"

#include "grammar/cell_components.h"
#include "grammar/cell_sets.h"
#include "symmetry/slippage.h"
#include "symmetry/symmetric_region.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

namespace dg {

std::string operation_name(OperationKind kind) {
  switch (kind) {
    case OperationKind::insert: return "insert";
    case OperationKind::remove: return "delete";
    case OperationKind::replace: return "replace";
  }
  return "replace";
}

namespace {

using Cells = std::vector<std::uint32_t>;

Cells cells_of(const std::vector<char>& mask) {
  Cells out;
  for (std::uint32_t c = 0; c < mask.size(); ++c)
    if (mask[c]) out.push_back(c);
  return out;
}

// The cells that `wall` cuts off from the `outer` cells: the parts of the surface without the
// wall that touch the wall and hold no outer cell (parts of the model the wall does not touch are
// not cut off by it). Parts with less surface than `min_part_area` (model units^2) are voxel
// noise, such as a cell the wall encloses that holds a sliver of a triangle, and do not count.
// Each part is explored from the wall only until it meets an outer cell, so the large outer side
// costs little.
Cells cut_off_side(const VoxelSurface& surface, const Cells& wall, const std::vector<char>& wall_mask,
                   const std::vector<char>& outer, double min_part_area) {
  std::vector<std::int32_t> part(surface.cell_count(), -1);
  std::vector<char> part_is_outer;
  std::vector<std::uint32_t> queue;
  Cells cut_off;
  for (std::uint32_t w : wall)
    for (std::uint32_t start : surface.neighbours(w)) {
      if (wall_mask[start] || part[start] >= 0) continue;
      const auto id = static_cast<std::int32_t>(part_is_outer.size());
      part_is_outer.push_back(0);
      part[start] = id;
      queue.assign(1, start);
      for (std::size_t head = 0; head < queue.size() && !part_is_outer[id]; ++head) {
        const std::uint32_t c = queue[head];
        if (outer[c]) {
          part_is_outer[id] = 1;
          break;
        }
        for (std::uint32_t nb : surface.neighbours(c)) {
          if (wall_mask[nb]) continue;
          if (part[nb] < 0) {
            part[nb] = id;
            queue.push_back(nb);
          } else if (part[nb] != id && part_is_outer[part[nb]]) {
            part_is_outer[id] = 1;  // joins a part already known to reach an outer cell
            break;
          }
        }
      }
      if (part_is_outer[id]) continue;
      // Explored to the end without an outer cell: the queue holds the whole part.
      double area = 0.0;
      for (std::uint32_t c : queue) area += surface.area(c);
      if (area >= min_part_area) cut_off.insert(cut_off.end(), queue.begin(), queue.end());
    }
  std::sort(cut_off.begin(), cut_off.end());
  return cut_off;
}

// Cells of `allowed` adjacent to a cell of `inside` and not in `inside` themselves.
Cells ring_around(const VoxelSurface& surface, const Cells& inside, const std::vector<char>& inside_mask,
                  const std::vector<char>& allowed) {
  Cells ring;
  for (std::uint32_t c : inside)
    for (std::uint32_t n : surface.neighbours(c))
      if (allowed[n] && !inside_mask[n]) ring.push_back(n);
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  return ring;
}

// Connected parts (26-adjacency within the band) of the ascending cells `band`: the part of
// each band cell, in band order, and their number in `count`. Works within the band only (a
// site's band is small next to the surface).
std::vector<std::size_t> band_parts(const VoxelSurface& surface, const Cells& band, std::size_t& count) {
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> part(band.size(), kNone);
  auto position = [&](std::uint32_t cell) -> std::size_t {
    const auto it = std::lower_bound(band.begin(), band.end(), cell);
    return it != band.end() && *it == cell ? static_cast<std::size_t>(it - band.begin()) : kNone;
  };
  count = 0;
  std::vector<std::size_t> queue;
  for (std::size_t start = 0; start < band.size(); ++start) {
    if (part[start] != kNone) continue;
    part[start] = count;
    queue.assign(1, start);
    for (std::size_t head = 0; head < queue.size(); ++head)
      for (std::uint32_t n : surface.neighbours(band[queue[head]]))
        if (const std::size_t i = position(n); i != kNone && part[i] == kNone) {
          part[i] = count;
          queue.push_back(i);
        }
    ++count;
  }
  return part;
}

// Whether a connected part of `band` (26-adjacency within the band) has no cell next to a cell
// of `docker_mask`: a stretch of seam that borders nothing the operation replaces.
bool has_part_away_from(const VoxelSurface& surface, const Cells& band, const std::vector<char>& docker_mask) {
  std::size_t parts = 0;
  const std::vector<std::size_t> part = band_parts(surface, band, parts);
  std::vector<char> borders(parts, 0);
  for (std::size_t i = 0; i < band.size(); ++i)
    for (std::uint32_t n : surface.neighbours(band[i]))
      if (docker_mask[n]) borders[part[i]] = 1;
  return std::find(borders.begin(), borders.end(), 0) != borders.end();
}

double area_of(const VoxelSurface& surface, const Cells& cells) {
  double area = 0.0;
  for (std::uint32_t c : cells) area += surface.area(c);
  return area;
}

// Slippage dimension of the planes inside the band cells: the motions that slide each connected
// part of the band along itself (a site made of loops around several stems slides along them).
std::size_t band_slippage(const VoxelSurface& surface, const Cells& band) {
  std::size_t part_count = 0;
  const std::vector<std::size_t> part = band_parts(surface, band, part_count);
  std::vector<OrientedPoints> parts(part_count);
  for (std::size_t i = 0; i < band.size(); ++i) {
    OrientedPoints& points = parts[part[i]];
    const Vec3 centre = surface.centre(band[i]);
    for (const CellPlane& plane : surface.planes(band[i])) {
      points.points.push_back(centre - (plane.normal.dot(centre) - plane.offset) * plane.normal);
      points.normals.push_back(plane.normal);
    }
  }
  return joint_slippage_dimension(parts);
}

// Everything needed to evaluate docker candidates for one motion.
struct MotionContext {
  const VoxelSurface& surface;
  const CellMatcher& matcher;
  RigidTransform transform;
  std::vector<char> symmetric;  // r-symmetric cells under transform
  double r;
};

// The docking site around docker cells `docker`, or nothing when it is not valid.
std::optional<DockingSite> evaluate(const MotionContext& m, const Cells& docker, Cells& touched_by_image) {
  const VoxelSurface& surface = m.surface;
  const std::size_t n = surface.cell_count();
  std::vector<char> docker_mask = mask_of(docker, n);
  const Cells ring1 = ring_around(surface, docker, docker_mask, m.symmetric);
  if (ring1.empty()) return std::nullopt;  // a whole non-symmetric part: nothing to cut
  std::vector<char> inner_mask = docker_mask;
  for (std::uint32_t c : ring1) inner_mask[c] = 1;
  const Cells ring2 = ring_around(surface, ring1, inner_mask, m.symmetric);
  Cells site = ring1;
  site.insert(site.end(), ring2.begin(), ring2.end());
  std::sort(site.begin(), site.end());
  std::vector<char> site_or_docker = docker_mask;
  for (std::uint32_t c : site) site_or_docker[c] = 1;
  const Cells outside = ring_around(surface, site, site_or_docker, m.symmetric);
  if (outside.empty()) return std::nullopt;  // nothing would remain outside the docker

  // The image of the site, and the images of the cells just outside it.
  // The band's image closes even where T does not carry the voxel grid onto itself.
  std::vector<char> image_site;
  if (m.matcher.image_of_cells(site, m.transform, image_site) > 0) return std::nullopt;
  touched_by_image = cells_of(image_site);
  std::vector<char> outer(n, 0);
  for (std::uint32_t c : outside) {
    const std::int64_t image = m.matcher.image_cell(c, m.transform);
    if (image >= 0) outer[static_cast<std::uint32_t>(image)] = 1;
  }
  // T(site) must split the model: cut off a part with at least one voxel face of surface.
  const Cells secondary = cut_off_side(surface, touched_by_image, image_site, outer, surface.eps() * surface.eps());
  if (secondary.empty()) return std::nullopt;

  DockingSite s;
  s.transform = m.transform;
  s.site = site;
  s.docker = docker;
  s.secondary_site = touched_by_image;
  s.secondary_docker = secondary;
  s.docker_area = area_of(surface, docker);
  s.secondary_docker_area = area_of(surface, secondary);
  s.stray_seam = has_part_away_from(surface, touched_by_image, mask_of(secondary, n));
  return s;
}

OperationKind classify(const DockingSite& s, std::size_t cell_count, double containment) {
  const std::vector<char> docker = mask_of(s.docker, cell_count);
  const std::vector<char> secondary = mask_of(s.secondary_docker, cell_count);
  const bool secondary_inside = share_inside(s.secondary_docker, docker) >= containment;
  const bool docker_inside = share_inside(s.docker, secondary) >= containment;
  // Dockers inside each other are the same piece: swapping them grows or shrinks nothing.
  if (secondary_inside && !docker_inside) return OperationKind::insert;
  if (docker_inside && !secondary_inside) return OperationKind::remove;
  return OperationKind::replace;
}

// T(D) lands on a cell that stays in place and lies farther than r from the seam.
bool inserted_docker_collides(const MotionContext& m, const DockingSite& s) {
  const VoxelSurface& surface = m.surface;
  const std::vector<double> seam_distance = surface.intrinsic_distance(s.secondary_site, 2.0 * m.r);
  const std::vector<char> replaced = mask_of(s.secondary_docker, surface.cell_count());
  for (std::uint32_t c : s.docker) {
    const std::int64_t hit = surface.find(surface.voxel_of(m.transform.apply(surface.centre(c))));
    if (hit < 0) continue;
    const auto cell = static_cast<std::uint32_t>(hit);
    if (!replaced[cell] && seam_distance[cell] > m.r) return true;
  }
  return false;
}

// Sites of one motion: every non-symmetric region (with dependent regions merged) that gives a
// valid site; each region ends up in at most one docker.
void sites_of_motion(const MotionContext& m, const DockingSiteOptions& options, DockingSiteResult& result) {
  const VoxelSurface& surface = m.surface;
  const std::size_t n = surface.cell_count();
  std::vector<char> non_symmetric(n, 0);
  for (std::uint32_t c = 0; c < n; ++c) non_symmetric[c] = !m.symmetric[c];
  std::size_t region_count = 0;
  const std::vector<std::int32_t> region = label_components(surface, non_symmetric, region_count);
  std::vector<Cells> region_cells(region_count);
  for (std::uint32_t c = 0; c < n; ++c)
    if (region[c] >= 0) region_cells[region[c]].push_back(c);
  result.stats.regions += region_count;

  std::vector<char> used(region_count, 0);
  for (std::size_t start = 0; start < region_count; ++start) {
    if (used[start]) continue;
    std::vector<std::size_t> group{start};
    std::optional<DockingSite> site;
    for (int round = 0; round <= options.max_merge_rounds; ++round) {
      Cells docker;
      for (std::size_t g : group) docker.insert(docker.end(), region_cells[g].begin(), region_cells[g].end());
      std::sort(docker.begin(), docker.end());
      Cells image;
      site = evaluate(m, docker, image);
      if (site || image.empty()) break;
      // Dependent regions: non-symmetric regions the site's image runs through or touches.
      std::vector<char> in_group(region_count, 0);
      for (std::size_t g : group) in_group[g] = 1;
      std::size_t before = group.size();
      for (std::uint32_t c : image) {
        auto consider = [&](std::uint32_t cell) {
          const std::int32_t id = region[cell];
          if (id >= 0 && !in_group[id] && !used[id]) {
            in_group[id] = 1;
            group.push_back(static_cast<std::size_t>(id));
          }
        };
        consider(c);
        for (std::uint32_t nb : surface.neighbours(c)) consider(nb);
      }
      if (group.size() == before) break;
    }
    if (!site) {
      ++result.stats.invalid;
      continue;
    }
    for (std::size_t g : group) used[g] = 1;
    site->regions = group.size();
    site->operation = classify(*site, n, options.containment);
    site->collides = inserted_docker_collides(m, *site);
    site->slippable_motions = band_slippage(surface, site->site);
    site->slippable = site->slippable_motions >= options.slippable_dimension;
    result.sites.push_back(std::move(*site));
  }
}

// r-symmetric cells of the inverse motion, grown from the images of the forward region and,
// given `parts`, into parts those do not reach (a point cloud's isolated outlier cells count as
// symmetric), as the forward region was.
std::vector<char> inverse_region(const VoxelSurface& surface, const CellMatcher& matcher, const DetectedSymmetry& symmetry,
                                 const RigidTransform& inverse, bool point_cloud, const SurfaceParts* parts) {
  const Cells& forward = symmetry.region.r_symmetric_cells;
  Cells seeds;
  const std::size_t step = std::max<std::size_t>(1, forward.size() / 64);
  for (std::size_t i = 0; i < forward.size(); i += step) {
    const std::int64_t image = matcher.image_cell(forward[i], symmetry.transform);
    if (image >= 0) seeds.push_back(static_cast<std::uint32_t>(image));
  }
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  const SymmetricRegion region = symmetric_region(matcher, surface, inverse, seeds, point_cloud, parts);
  return mask_of(region.r_symmetric_cells, surface.cell_count());
}

}  // namespace

DockingSiteResult find_docking_sites(const PreparedModel& prepared, const SymmetryResult& symmetries,
                                     const DockingSiteOptions& options, const ProgressCallback& progress) {
  DockingSiteResult result;
  const VoxelSurface& surface = prepared.surface;
  if (surface.cell_count() == 0) return result;
  const bool point_cloud = prepared.model.is_point_cloud();
  const CellMatcher matcher(surface, point_cloud ? &prepared.model.cloud : nullptr, symmetries.region);
  // One member per family, the smallest power found: higher powers (2t, 3t, ...) repeat its
  // operations.
  std::vector<int> smallest_power(symmetries.families.size(), std::numeric_limits<int>::max());
  for (const DetectedSymmetry& s : symmetries.symmetries)
    if (s.family < smallest_power.size()) smallest_power[s.family] = std::min(smallest_power[s.family], std::abs(s.power));
  std::vector<std::size_t> chosen;
  std::vector<char> family_taken(symmetries.families.size(), 0);
  for (std::size_t i = 0; i < symmetries.symmetries.size(); ++i) {
    const DetectedSymmetry& s = symmetries.symmetries[i];
    if (s.family < family_taken.size()) {
      if (family_taken[s.family] || std::abs(s.power) != smallest_power[s.family]) continue;
      family_taken[s.family] = 1;
    }
    if (chosen.size() < options.max_symmetries)
      chosen.push_back(i);
    else
      ++result.stats.symmetries_skipped;
  }
  const std::optional<SurfaceParts> parts = point_cloud ? std::nullopt : std::optional<SurfaceParts>(surface_parts(surface));
  // Each motion (symmetry and direction) is independent: computed in parallel, joined in order.
  std::vector<DockingSiteResult> per_motion(2 * chosen.size());
  parallel_for_reporting(per_motion.size(), progress, "docking sites", [&](std::size_t m) {
    const std::size_t i = chosen[m / 2];
    const bool inverse = m % 2 == 1;
    const DetectedSymmetry& symmetry = symmetries.symmetries[i];
    const RigidTransform t = inverse ? symmetry.transform.inverse() : symmetry.transform;
    std::vector<char> symmetric = inverse ? inverse_region(surface, matcher, symmetry, t, point_cloud, parts ? &*parts : nullptr)
                                          : mask_of(symmetry.region.r_symmetric_cells, surface.cell_count());
    const MotionContext context{surface, matcher, t, std::move(symmetric), surface.r()};
    DockingSiteResult& local = per_motion[m];
    local.stats.motions = 1;
    sites_of_motion(context, options, local);
    for (DockingSite& site : local.sites) {
      site.symmetry = i;
      site.inverse = inverse;
    }
  });
  report_progress(progress, "docking sites", 1.0);
  for (DockingSiteResult& local : per_motion) {
    result.stats.motions += local.stats.motions;
    result.stats.regions += local.stats.regions;
    result.stats.invalid += local.stats.invalid;
    for (DockingSite& site : local.sites) result.sites.push_back(std::move(site));
  }
  return result;
}

}  // namespace dg
