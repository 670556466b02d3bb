#include "grammar/site_loops.h"

#include "grammar/cell_sets.h"
#include "geometry/union_find.h"

#include <algorithm>
#include <numeric>

namespace dg {
namespace {

// Position of `cell` in the ascending list `cells`, or -1.
std::int64_t index_in(const std::vector<std::uint32_t>& cells, std::uint32_t cell) {
  const auto it = std::lower_bound(cells.begin(), cells.end(), cell);
  return it != cells.end() && *it == cell ? it - cells.begin() : -1;
}

// Labels the cells reachable from `start` through cells whose flag in `allowed` is set with
// `id` (cells labelled already stop the walk).
void flood(const VoxelSurface& surface, std::uint32_t start, const std::vector<char>& allowed, std::int32_t id,
           std::vector<std::int32_t>& label) {
  std::vector<std::uint32_t> queue{start};
  label[start] = id;
  for (std::size_t head = 0; head < queue.size(); ++head)
    for (std::uint32_t n : surface.neighbours(queue[head]))
      if (allowed[n] && label[n] < 0) {
        label[n] = id;
        queue.push_back(n);
      }
}

}  // namespace

SiteLoops site_loops(const VoxelSurface& surface, const std::vector<std::uint32_t>& site, const std::vector<std::uint32_t>& docker) {
  SiteLoops out;
  out.loop_of.assign(site.size(), -1);
  std::vector<std::size_t> queue;
  for (std::size_t i = 0; i < site.size(); ++i) {
    if (out.loop_of[i] >= 0) continue;
    const auto id = static_cast<std::int32_t>(out.representative.size());
    out.representative.push_back(site[i]);
    out.loop_of[i] = id;
    queue.assign(1, i);
    for (std::size_t head = 0; head < queue.size(); ++head)
      for (std::uint32_t n : surface.neighbours(site[queue[head]])) {
        const std::int64_t j = index_in(site, n);
        if (j >= 0 && out.loop_of[static_cast<std::size_t>(j)] < 0) {
          out.loop_of[static_cast<std::size_t>(j)] = id;
          queue.push_back(static_cast<std::size_t>(j));
        }
      }
  }
  // The rest of the model: every cell outside the docker, walked from each loop.
  const std::vector<char> in_docker = mask_of(docker, surface.cell_count());
  std::vector<char> outside(in_docker.size());
  for (std::size_t c = 0; c < outside.size(); ++c) outside[c] = !in_docker[c];
  std::vector<std::int32_t> rest(surface.cell_count(), -1);
  std::int32_t rest_parts = 0;
  for (std::uint32_t cell : out.representative) {
    if (rest[cell] < 0) flood(surface, cell, outside, rest_parts++, rest);
    out.rest_part.push_back(static_cast<std::uint32_t>(rest[cell]));
  }
  // The docker's parts and the loops each touches.
  std::vector<std::int32_t> part(surface.cell_count(), -1);
  std::int32_t parts = 0;
  for (std::uint32_t c : docker)
    if (part[c] < 0) flood(surface, c, in_docker, parts++, part);
  out.docker_parts.resize(static_cast<std::size_t>(parts));
  for (std::size_t i = 0; i < site.size(); ++i)
    for (std::uint32_t n : surface.neighbours(site[i]))
      if (part[n] >= 0) out.docker_parts[static_cast<std::size_t>(part[n])].push_back(static_cast<std::uint32_t>(out.loop_of[i]));
  for (auto& loops : out.docker_parts) {
    std::sort(loops.begin(), loops.end());
    loops.erase(std::unique(loops.begin(), loops.end()), loops.end());
  }
  std::erase_if(out.docker_parts, [](const std::vector<std::uint32_t>& loops) { return loops.empty(); });
  return out;
}

std::optional<std::size_t> joined_loop_groups(const VoxelSurface& surface, const std::vector<std::uint32_t>& at_site,
                                              const SiteLoops& at, const SiteLoops& from, const RigidTransform& from_to_at) {
  const auto loops = static_cast<std::uint32_t>(at.representative.size());
  std::vector<std::uint32_t> parent(loops);
  std::iota(parent.begin(), parent.end(), 0u);
  auto join = [&](std::uint32_t a, std::uint32_t b) { parent[find_root(parent, a)] = find_root(parent, b); };
  for (std::uint32_t a = 0; a < loops; ++a)
    for (std::uint32_t b = a + 1; b < loops; ++b)
      if (at.rest_part[a] == at.rest_part[b]) join(a, b);
  // Each loop of `from` onto the loop of `at` holding its representative's mapped centre (or a
  // cell next to it).
  std::vector<std::uint32_t> image;
  for (std::uint32_t cell : from.representative) {
    const VoxelCoord v = surface.voxel_of(from_to_at.apply(surface.centre(cell)));
    std::int64_t found = -1;
    for (int d = 0; d < 27 && found < 0; ++d) {
      const int step = (d + 13) % 27;  // the voxel itself first
      const std::int64_t c = surface.find({v[0] + step / 9 - 1, v[1] + (step / 3) % 3 - 1, v[2] + step % 3 - 1});
      if (c >= 0) found = index_in(at_site, static_cast<std::uint32_t>(c));
    }
    if (found < 0) return std::nullopt;
    image.push_back(static_cast<std::uint32_t>(at.loop_of[static_cast<std::size_t>(found)]));
  }
  for (const std::vector<std::uint32_t>& touched : from.docker_parts)
    for (std::uint32_t l : touched) join(image[touched.front()], image[l]);
  std::size_t groups = 0;
  for (std::uint32_t l = 0; l < loops; ++l) groups += find_root(parent, l) == l ? 1 : 0;
  return groups;
}

}  // namespace dg
