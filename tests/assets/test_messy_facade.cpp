// The damaged facade: the defects are there, the shape and ground truth are the facade's.

#include "assets/generator/asset.h"
#include "geometry/topology.h"
#include "tests/assets/asset_checks.h"

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <map>
#include <set>

using dg::assets::make_asset;

namespace {

/// Distinct positions, compared exactly.
std::set<std::array<double, 3>> distinct_positions(const dg::TriangleMesh& mesh) {
  std::set<std::array<double, 3>> result;
  for (const dg::Vec3& p : mesh.positions) result.insert({p.x(), p.y(), p.z()});
  return result;
}

/// The mesh with vertices of exactly equal position merged (first occurrence kept).
dg::TriangleMesh welded(const dg::TriangleMesh& mesh) {
  std::map<std::array<double, 3>, std::uint32_t> index;
  dg::TriangleMesh result;
  std::vector<std::uint32_t> remap(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const dg::Vec3& p = mesh.positions[v];
    const auto [it, inserted] = index.try_emplace({p.x(), p.y(), p.z()}, static_cast<std::uint32_t>(result.positions.size()));
    if (inserted) result.positions.push_back(p);
    remap[v] = it->second;
  }
  for (const dg::Triangle& t : mesh.triangles) result.triangles.push_back({remap[t[0]], remap[t[1]], remap[t[2]]});
  return result;
}

}  // namespace

TEST_CASE("messy facade carries the promised damage", "[assets]") {
  const auto clean = make_asset("facade", {{"columns", 3}, {"rows", 4}});
  const auto messy = make_asset("messy_facade", {{"columns", 3}, {"rows", 4}});
  const nlohmann::json& damage = messy.ground_truth.at("damage");
  CHECK(messy.name == "messy_facade_3x4");

  const dg::EdgeStatistics raw = dg::edge_statistics(messy.mesh);
  CHECK(raw.boundary_edges > 0);  // unwelded top face
  CHECK(raw.non_manifold_edges > 0);
  CHECK_FALSE(dg::is_closed_and_oriented(messy.mesh));

  // Unwelded vertices: positions repeated under different indices.
  CHECK(messy.mesh.positions.size() - distinct_positions(messy.mesh).size() == damage["unwelded_vertices"].get<std::size_t>());
  CHECK(damage["unwelded_vertices"].get<int>() > 0);

  // Duplicated faces: the same three welded vertices used twice.
  const dg::TriangleMesh weld = welded(messy.mesh);
  std::map<std::array<std::uint32_t, 3>, int> uses;
  for (dg::Triangle t : weld.triangles) {
    std::sort(t.begin(), t.end());
    ++uses[t];
  }
  const auto duplicated = std::count_if(uses.begin(), uses.end(), [](const auto& entry) { return entry.second > 1; });
  CHECK(duplicated == damage["duplicated_faces"].get<long>());

  // Slivers: near-zero area triangles.
  const double typical = clean.mesh.area() / static_cast<double>(clean.mesh.triangles.size());
  std::size_t slivers = 0;
  for (std::size_t t = 0; t < messy.mesh.triangles.size(); ++t)
    if (0.5 * messy.mesh.area_vector(t).norm() < 1e-5 * typical) ++slivers;
  CHECK(slivers == damage["sliver_triangles"].get<std::size_t>());

  // After welding: still non-manifold (fin, duplicates), the clean positions plus the few new
  // points that lie on existing edges (slivers) or form the fin apex.
  CHECK(dg::edge_statistics(weld).non_manifold_edges > 0);
  const auto clean_positions = distinct_positions(clean.mesh);
  const auto messy_positions = distinct_positions(messy.mesh);
  CHECK(std::includes(messy_positions.begin(), messy_positions.end(), clean_positions.begin(), clean_positions.end()));
  CHECK(messy_positions.size() - clean_positions.size() == damage["new_positions"].get<std::size_t>());
  CHECK(messy.mesh.bounds().min == clean.mesh.bounds().min);

  // Same transforms and counts as the clean facade.
  CHECK(messy.ground_truth["repetitions"] == clean.ground_truth["repetitions"]);
  CHECK(messy.ground_truth["grids"] == clean.ground_truth["grids"]);
  CHECK(messy.ground_truth["triangle_count"].get<std::size_t>() == messy.mesh.triangles.size());
  CHECK(messy.ground_truth["clean"]["triangle_count"].get<std::size_t>() == clean.mesh.triangles.size());
}
