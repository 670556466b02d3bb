#include "grammar/material_hint.h"

#include "geometry/closest_point.h"
#include "geometry/union_find.h"

#include <cmath>
#include <numbers>
#include <numeric>

namespace dg {
namespace {

// A material keeps its own class when it lands on itself for this share of its mapped area ...
constexpr double kOwnClassShare = 0.8;
// ... else it joins the materials it lands on (or that land on it) for this share.
constexpr double kSwapShare = 0.1;
// The lighter search for the swaps: keypoints kept, keypoints used as vote sources, pairs
// voted and candidates verified (the full search: 20000, 600, 3M, 80).
constexpr std::size_t kLightPairs = 200'000;
constexpr std::size_t kLightVerified = 16;
constexpr std::size_t kLightSources = 150;
constexpr std::size_t kLightKeypoints = 4000;

// Material of the triangle lying in the plane of (q, normal) at q, or -1 (a triangle of the
// voxel holding q within `tolerance` whose normal agrees within `min_cos`).
long material_at(const PreparedModel& prepared, const Vec3& q, const Vec3& normal, double tolerance, double min_cos) {
  const TriangleMesh& mesh = prepared.model.mesh;
  const std::int64_t cell = prepared.surface.find(prepared.surface.voxel_of(q));
  if (cell < 0) return -1;
  for (std::uint32_t t : prepared.surface.triangles(static_cast<std::uint32_t>(cell))) {
    const Vec3 area_vector = mesh.area_vector(t);
    if (area_vector.norm() <= 0.0 || area_vector.normalized().dot(normal) < min_cos) continue;
    const auto [a, b, c] = mesh.corners(t);
    if ((closest_point_on_triangle(q, a, b, c) - q).norm() <= tolerance) return mesh.materials[t];
  }
  return -1;
}

bool usable_name(const std::string& name) { return name.find_first_of(",*'\"") == std::string::npos; }

// Counts of the grids of a prepared model.
std::vector<std::vector<int>> grid_counts(const PreparedModel& prepared, const SymmetryResult& symmetries) {
  std::vector<std::vector<int>> counts;
  for (const GridRule& grid : find_grids(prepared, symmetries)) counts.push_back(exemplar_counts(grid));
  return counts;
}

}  // namespace

std::vector<std::vector<double>> material_swaps(const PreparedModel& prepared, const SymmetryResult& symmetries,
                                                std::size_t translations) {
  const TriangleMesh& mesh = prepared.model.mesh;
  const std::size_t materials = prepared.model.materials.size();
  std::vector<std::vector<double>> swaps(materials, std::vector<double>(materials, 0.0));
  if (!mesh.has_materials()) return swaps;
  const double tolerance = 0.1 * prepared.surface.eps();
  const double min_cos = std::cos(2.5 * std::numbers::pi / 180.0);
  std::size_t used = 0;
  for (const DetectedSymmetry& symmetry : symmetries.symmetries) {
    if (symmetry.kind != "translation") continue;
    if (used++ == translations) break;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const Vec3 area_vector = mesh.area_vector(t);
      const double length = area_vector.norm();
      if (length <= 0.0 || mesh.materials[t] >= materials) continue;
      const auto [a, b, c] = mesh.corners(t);
      const Vec3 image = symmetry.transform.apply((a + b + c) / 3.0);
      const long landed = material_at(prepared, image, symmetry.transform.apply_direction(area_vector / length), tolerance, min_cos);
      if (landed >= 0 && static_cast<std::size_t>(landed) < materials) swaps[mesh.materials[t]][static_cast<std::size_t>(landed)] += 0.5 * length;
    }
  }
  return swaps;
}

std::vector<std::vector<std::uint32_t>> interchangeable_materials(const std::vector<std::vector<double>>& swaps) {
  const auto n = static_cast<std::uint32_t>(swaps.size());
  std::vector<double> mapped(n, 0.0);
  for (std::uint32_t a = 0; a < n; ++a) mapped[a] = std::accumulate(swaps[a].begin(), swaps[a].end(), 0.0);
  auto share = [&](std::uint32_t a, std::uint32_t b) { return mapped[a] > 0.0 ? swaps[a][b] / mapped[a] : 0.0; };
  auto own_class = [&](std::uint32_t a) { return mapped[a] <= 0.0 || share(a, a) >= kOwnClassShare; };
  std::vector<std::uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b)
      if (!own_class(a) && !own_class(b) && std::max(share(a, b), share(b, a)) >= kSwapShare)
        parent[find_root(parent, b)] = find_root(parent, a);
  std::vector<std::vector<std::uint32_t>> groups;
  std::vector<long> group_of(n, -1);
  for (std::uint32_t a = 0; a < n; ++a) {
    const std::uint32_t r = find_root(parent, a);
    if (group_of[r] < 0) {
      group_of[r] = static_cast<long>(groups.size());
      groups.emplace_back();
    }
    groups[static_cast<std::size_t>(group_of[r])].push_back(a);
  }
  std::erase_if(groups, [](const std::vector<std::uint32_t>& g) { return g.size() < 2; });
  return groups;
}

bool material_hint_applies(const PreparedModel& prepared, const PrepareOptions& options, std::size_t grids_found) {
  return !prepared.model.is_point_cloud() && prepared.model.mesh.has_materials() && prepared.model.materials.size() >= 2 &&
         grids_found == 0 && !options.match_materials && options.same_materials.empty();
}

std::optional<MaterialHint> material_grouping(const PreparedModel& prepared, const PrepareOptions& options,
                                              const SymmetryOptions& symmetry_options, std::size_t grids_found,
                                              const ProgressCallback& progress) {
  if (!material_hint_applies(prepared, options, grids_found)) return std::nullopt;
  const std::vector<Material>& materials = prepared.model.materials;
  report_progress(progress, "material hint", 0.0);
  // A lighter search (the repeats sought have strong support): which materials the translations
  // swap, and whether matching materials in those groups gives any grid.
  SymmetryOptions light = symmetry_options;
  light.candidates.max_pairs = kLightPairs;
  light.max_verified = kLightVerified;
  light.candidates.max_sources = kLightSources;
  light.max_keypoints = kLightKeypoints;
  PrepareOptions matched = options;
  matched.match_materials = true;
  const PreparedModel painted = prepare_model(prepared.model, matched);
  const SymmetryResult painted_symmetries = detect_symmetries(painted, light);
  const std::vector<std::vector<std::uint32_t>> groups = interchangeable_materials(material_swaps(painted, painted_symmetries));
  MaterialHint hint;
  hint.options = matched;
  for (const std::vector<std::uint32_t>& group : groups) {
    std::vector<std::string> names;
    std::string list;
    for (std::uint32_t m : group) {
      if (!usable_name(materials[m].name)) return std::nullopt;
      names.push_back(materials[m].name);
      list += (list.empty() ? "" : ",") + materials[m].name;
    }
    hint.groups.push_back(std::move(names));
    hint.options.same_materials.push_back(std::move(list));
  }
  report_progress(progress, "material hint", 0.5);
  const PreparedModel regrouped = groups.empty() ? PreparedModel{} : prepare_model(prepared.model, hint.options);
  const PreparedModel& tried = groups.empty() ? painted : regrouped;
  const bool grids = !grid_counts(tried, groups.empty() ? painted_symmetries : detect_symmetries(tried, light)).empty();
  report_progress(progress, "material hint", 1.0);
  if (!grids) return std::nullopt;
  return hint;
}

std::optional<MaterialHint> material_hint(const PreparedModel& prepared, const PrepareOptions& options,
                                          const SymmetryOptions& symmetry_options, std::size_t grids_found,
                                          const ProgressCallback& progress) {
  std::optional<MaterialHint> hint = material_grouping(prepared, options, symmetry_options, grids_found, progress);
  if (!hint) return std::nullopt;
  const PreparedModel grouped = prepare_model(prepared.model, hint->options);
  hint->grid_counts = grid_counts(grouped, detect_symmetries(grouped, symmetry_options));
  if (hint->grid_counts.empty()) return std::nullopt;
  return hint;
}

}  // namespace dg
