#include "grammar/whole_parts.h"

#include "geometry/topology.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace dg {
namespace {

// Voxels sorted into blocks of `size` voxels a side.
class VoxelBlocks {
 public:
  VoxelBlocks(const std::vector<VoxelCoord>& voxels, int size) : size_(size) {
    for (const VoxelCoord& v : voxels) blocks_[block_of(v)].push_back(v);
  }

  // Calls `visit(a, b)` for every voxel a with the first voxel b of its own block and of each
  // block next to it (voxels of neighbouring blocks lie under 2 size voxels apart): joining each
  // pair joins all voxels of neighbouring blocks.
  template <class Visit>
  void neighbouring_blocks(const Visit& visit) const {
    for (const auto& [key, voxels] : blocks_)
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz) {
            const auto found = blocks_.find({key[0] + dx, key[1] + dy, key[2] + dz});
            if (found == blocks_.end()) continue;
            for (const VoxelCoord& v : voxels) visit(v, found->second.front());
          }
  }

 private:
  using Key = std::array<std::int32_t, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      return static_cast<std::size_t>(k[0]) * 73856093u ^ static_cast<std::size_t>(k[1]) * 19349663u ^
             static_cast<std::size_t>(k[2]) * 83492791u;
    }
  };
  Key block_of(const VoxelCoord& v) const {
    auto floor_div = [&](std::int32_t x) { return x >= 0 ? x / size_ : -((-x + size_ - 1) / size_); };
    return {floor_div(v[0]), floor_div(v[1]), floor_div(v[2])};
  }

  std::int32_t size_;
  std::unordered_map<Key, std::vector<VoxelCoord>, KeyHash> blocks_;
};

std::uint32_t root(std::vector<std::uint32_t>& parent, std::uint32_t a) {
  while (parent[a] != a) a = parent[a] = parent[parent[a]];
  return a;
}

// Whether some part has a copy moved by `t`: a part of the same area (within 0.1 %) whose bounding
// box is its own moved by t (within `tolerance`). Without one there is no row of parts.
bool has_moved_copy(const std::vector<double>& area, const std::vector<BoundingBox>& box, const Vec3& t, double tolerance) {
  std::vector<std::size_t> by_area(area.size());
  std::iota(by_area.begin(), by_area.end(), std::size_t{0});
  std::sort(by_area.begin(), by_area.end(), [&](std::size_t a, std::size_t b) { return area[a] < area[b]; });
  for (std::size_t i = 0; i < by_area.size(); ++i)
    for (std::size_t j = i + 1; j < by_area.size() && area[by_area[j]] <= area[by_area[i]] * 1.001; ++j) {
      const BoundingBox& a = box[by_area[i]];
      const BoundingBox& b = box[by_area[j]];
      for (const Vec3& step : {t, Vec3(-t)})
        if ((a.min + step - b.min).cwiseAbs().maxCoeff() <= tolerance && (a.max + step - b.max).cwiseAbs().maxCoeff() <= tolerance)
          return true;
    }
  return false;
}

// The model without the triangles flagged in `removed`: mesh, feature edges and voxel surface on
// the model's grid (same r, eps and material classes), keeping the model's cleaning report.
PreparedModel without_triangles(const PreparedModel& prepared, const std::vector<char>& removed) {
  const TriangleMesh& mesh = prepared.model.mesh;
  PreparedModel rest;
  rest.cleaning = prepared.cleaning;
  rest.material_classes = prepared.material_classes;
  constexpr std::uint32_t kGone = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> renumbered(mesh.positions.size(), kGone);
  TriangleMesh& part = rest.model.mesh;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (removed[t]) continue;
    Triangle tri;
    for (int k = 0; k < 3; ++k) {
      std::uint32_t& v = renumbered[mesh.triangles[t][k]];
      if (v == kGone) {
        v = static_cast<std::uint32_t>(part.positions.size());
        part.positions.push_back(mesh.positions[mesh.triangles[t][k]]);
      }
      tri[k] = v;
    }
    part.triangles.push_back(tri);
    if (mesh.has_materials()) part.materials.push_back(mesh.materials[t]);
  }
  for (FeatureEdge edge : prepared.feature_edges) {
    const std::uint32_t a = renumbered[edge.v0], b = renumbered[edge.v1];
    if (a == kGone || b == kGone) continue;
    edge.v0 = std::min(a, b);
    edge.v1 = std::max(a, b);
    rest.feature_edges.push_back(edge);
  }
  std::sort(rest.feature_edges.begin(), rest.feature_edges.end(),
            [](const FeatureEdge& x, const FeatureEdge& y) { return std::tie(x.v0, x.v1) < std::tie(y.v0, y.v1); });
  VoxelSurfaceOptions options;
  options.r = prepared.surface.r();
  options.eps = prepared.surface.eps();
  options.material_classes = prepared.material_classes;
  rest.surface = build_voxel_surface(part, rest.feature_edges, options);
  return rest;
}

}  // namespace

ModelParts model_parts(const TriangleMesh& mesh) {
  ModelParts parts;
  std::size_t count = 0;
  parts.part = triangle_components(mesh, &count);
  parts.area.assign(count, 0.0);
  parts.box.resize(count);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    parts.area[parts.part[t]] += 0.5 * mesh.area_vector(t).norm();
    for (const Vec3& p : mesh.corners(t)) parts.box[parts.part[t]].add(p);
  }
  return parts;
}

bool WholeParts::empty() const { return std::find(kept.begin(), kept.end(), 1) == kept.end(); }

WholeParts whole_parts(const PreparedModel& prepared, const ModelParts& model, const DetectedSymmetry& symmetry,
                       const RegionOptions& matching) {
  const TriangleMesh& mesh = prepared.model.mesh;
  const VoxelSurface& surface = prepared.surface;
  const std::vector<std::uint32_t>& part_of = model.part;
  const std::size_t parts = model.area.size();
  WholeParts whole;
  whole.kept.assign(parts, 0);
  if (!has_moved_copy(model.area, model.box, symmetry.transform.translation, surface.eps())) return whole;

  // Candidates: small parts with a cell of their own that is not symmetric.
  const double largest = kWholePartShare * mesh.area();
  std::vector<char> known_symmetric(surface.cell_count(), 0);
  for (std::uint32_t c : symmetry.region.symmetric_cells) known_symmetric[c] = 1;
  const CellMatcher matcher(surface, nullptr, matching);
  const RigidTransform inverse = symmetry.transform.inverse();
  for (std::uint32_t c = 0; c < surface.cell_count(); ++c) {
    const auto triangles = surface.triangles(c);
    if (triangles.empty() || known_symmetric[c]) continue;
    const std::uint32_t p = part_of[triangles.front()];
    if (whole.kept[p] || model.area[p] > largest) continue;
    if (std::all_of(triangles.begin(), triangles.end(), [&](std::uint32_t t) { return part_of[t] == p; }) &&
        !matcher.symmetric(c, symmetry.transform, inverse))
      whole.kept[p] = 1;
  }

  if (whole.empty()) return whole;

  // Groups: parts in the same or neighbouring blocks of ceil(r / eps) voxels (within about 2 r)
  // move together.
  const int reach = static_cast<int>(std::ceil(surface.r() / surface.eps()));
  std::vector<std::uint32_t> parent(parts);
  std::iota(parent.begin(), parent.end(), 0u);
  std::unordered_map<std::uint32_t, std::uint32_t> part_in;  // a kept part of each cell holding one
  std::vector<VoxelCoord> voxels;
  for (std::uint32_t c = 0; c < surface.cell_count(); ++c)
    for (std::uint32_t t : surface.triangles(c))
      if (whole.kept[part_of[t]]) {
        const auto [at, added] = part_in.emplace(c, part_of[t]);
        if (added) voxels.push_back(surface.coord(c));
        parent[root(parent, part_of[t])] = root(parent, at->second);
      }
  VoxelBlocks(voxels, reach).neighbouring_blocks([&](const VoxelCoord& a, const VoxelCoord& b) {
    const auto cell = [&](const VoxelCoord& v) { return static_cast<std::uint32_t>(surface.find(v)); };
    parent[root(parent, part_in.at(cell(a)))] = root(parent, part_in.at(cell(b)));
  });
  whole.group.resize(parts);
  for (std::uint32_t p = 0; p < parts; ++p) whole.group[p] = root(parent, p);

  // The rest, with the motion's symmetric region on it.
  std::vector<char> removed(mesh.triangles.size(), 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) removed[t] = whole.kept[part_of[t]];
  whole.rest = without_triangles(prepared, removed);
  whole.motion = symmetry;
  whole.motion.region = tested_symmetric_region(CellMatcher(whole.rest.surface, nullptr, matching), whole.rest.surface, symmetry.transform);
  return whole;
}

}  // namespace dg
