#include "grammar/site_loops.h"

#include "grammar/cell_components.h"
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

}  // namespace

SiteLoops site_loops(const VoxelSurface& surface, const std::vector<std::uint32_t>& site, const std::vector<std::uint32_t>& docker) {
  SiteLoops out;
  std::size_t count = 0;
  const std::vector<std::int32_t> loop = label_components(surface, mask_of(site, surface.cell_count()), count);
  out.representative.assign(count, 0);
  out.loop_of.reserve(site.size());
  for (auto c = site.rbegin(); c != site.rend(); ++c) out.representative[static_cast<std::size_t>(loop[*c])] = *c;  // lowest cell
  for (std::uint32_t c : site) out.loop_of.push_back(loop[c]);
  // The rest of the model (every cell outside the docker) and the docker, in connected parts.
  std::vector<char> mask = mask_of(docker, surface.cell_count());
  const std::vector<std::int32_t> part = label_components(surface, mask, count);
  out.docker_parts.resize(count);
  // Labelling the rest walks nearly the whole surface; a single loop has no other to join.
  if (out.representative.size() > 1) {
    for (char& flag : mask) flag = !flag;  // now the cells outside the docker
    const std::vector<std::int32_t> rest = label_components(surface, mask, count);
    for (std::uint32_t cell : out.representative) out.rest_part.push_back(static_cast<std::uint32_t>(rest[cell]));
  } else {
    out.rest_part.assign(out.representative.size(), 0);
  }
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
