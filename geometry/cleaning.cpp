// Exact weld, degenerate removal and the cleaning report.

#include "geometry/cleaning.h"

#include "geometry/topology.h"

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace dg {

namespace {

bool less_position(const Vec3& a, const Vec3& b) {
  if (a.x() != b.x()) return a.x() < b.x();
  if (a.y() != b.y()) return a.y() < b.y();
  return a.z() < b.z();
}

/// Maps every position to the index of the first position equal to it.
std::vector<std::uint32_t> first_equal_position(const std::vector<Vec3>& positions) {
  std::vector<std::uint32_t> order(positions.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    if (positions[a] != positions[b]) return less_position(positions[a], positions[b]);
    return a < b;
  });
  std::vector<std::uint32_t> first(positions.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j < order.size() && positions[order[j]] == positions[order[i]]) first[order[j++]] = order[i];
    i = j;
  }
  return first;
}

/// Keeps the entries whose `keep` flag is set, in order; returns old index -> new index.
std::vector<std::uint32_t> compact_positions(std::vector<Vec3>& positions, const std::vector<bool>& keep) {
  std::vector<std::uint32_t> new_index(positions.size(), 0);
  std::uint32_t next = 0;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!keep[i]) continue;
    new_index[i] = next;
    positions[next++] = positions[i];
  }
  positions.resize(next);
  return new_index;
}

std::size_t count_duplicate_triangles(const std::vector<Triangle>& triangles) {
  std::vector<Triangle> keys(triangles);
  for (Triangle& key : keys) std::sort(key.begin(), key.end());
  std::sort(keys.begin(), keys.end());
  std::size_t duplicates = 0;
  for (std::size_t i = 1; i < keys.size(); ++i) duplicates += keys[i] == keys[i - 1] ? 1 : 0;
  return duplicates;
}

nlohmann::json bounds_json(const BoundingBox& box) {
  if (box.empty()) return nullptr;
  return {{"min", {box.min.x(), box.min.y(), box.min.z()}}, {"max", {box.max.x(), box.max.y(), box.max.z()}}};
}

}  // namespace

bool nearly_collinear(const Vec3& a, const Vec3& b, const Vec3& c, double collinear_tolerance) {
  const double longest_squared = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  return (b - a).cross(c - a).norm() <= collinear_tolerance * longest_squared;
}

bool is_degenerate(const TriangleMesh& mesh, const Triangle& t, double collinear_tolerance) {
  if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return true;
  return nearly_collinear(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]], collinear_tolerance);
}

CleaningReport clean_mesh(TriangleMesh& mesh, const CleaningOptions& options) {
  CleaningReport report;
  report.input_vertices = mesh.positions.size();
  report.input_triangles = mesh.triangles.size();

  // Exact weld: representatives are first occurrences, so compacting keeps their order.
  const std::vector<std::uint32_t> first = first_equal_position(mesh.positions);
  std::vector<bool> keep(mesh.positions.size());
  for (std::size_t i = 0; i < first.size(); ++i) keep[i] = first[i] == i;
  const std::vector<std::uint32_t> welded_index = compact_positions(mesh.positions, keep);
  report.welded_vertices = mesh.positions.size();
  for (Triangle& t : mesh.triangles) {
    for (std::uint32_t& index : t) index = welded_index[first[index]];
  }

  const bool has_materials = mesh.has_materials();
  std::size_t kept = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const bool degenerate = is_degenerate(mesh, mesh.triangles[t], options.collinear_tolerance);
    report.degenerate_dropped += degenerate ? 1 : 0;
    if (degenerate && options.drop_degenerate) continue;
    if (has_materials) mesh.materials[kept] = mesh.materials[t];
    mesh.triangles[kept++] = mesh.triangles[t];
  }
  mesh.triangles.resize(kept);
  if (has_materials) mesh.materials.resize(kept);

  std::vector<bool> used(mesh.positions.size(), false);
  for (const Triangle& t : mesh.triangles) {
    for (std::uint32_t index : t) used[index] = true;
  }
  const std::vector<std::uint32_t> used_index = compact_positions(mesh.positions, used);
  for (Triangle& t : mesh.triangles) {
    for (std::uint32_t& index : t) index = used_index[index];
  }

  report.vertices = mesh.positions.size();
  report.triangles = mesh.triangles.size();
  report.duplicate_triangles = count_duplicate_triangles(mesh.triangles);
  const EdgeStatistics edges = edge_statistics(mesh);
  report.non_manifold_edges = edges.non_manifold_edges;
  report.boundary_edges = edges.boundary_edges;
  report.inconsistent_edges = edges.inconsistent_edges;
  report.closed_and_oriented = edges.edges > 0 && edges.boundary_edges == 0 && edges.non_manifold_edges == 0 &&
                               edges.inconsistent_edges == 0;
  triangle_components(mesh, &report.components);
  report.bounds = mesh.bounds();
  return report;
}

CleaningReport clean_point_cloud(PointCloud& cloud) {
  CleaningReport report;
  report.point_cloud = true;
  report.input_vertices = cloud.positions.size();
  const bool with_normals = cloud.has_normals();
  if (!with_normals) cloud.normals.clear();

  std::vector<bool> keep(cloud.positions.size(), true);
  if (with_normals) {
    for (std::size_t i = 0; i < cloud.normals.size(); ++i) {
      const double length = cloud.normals[i].norm();
      if (std::isfinite(length) && length > 0.0) {
        cloud.normals[i] /= length;
      } else {
        keep[i] = false;
        ++report.invalid_normals_dropped;
      }
    }
  }
  const std::vector<std::uint32_t> first = first_equal_position(cloud.positions);
  // A dropped point does not shadow a later copy of its position: the first kept copy survives.
  std::vector<bool> position_taken(cloud.positions.size(), false);
  for (std::size_t i = 0; i < cloud.positions.size(); ++i) {
    if (!keep[i]) continue;
    if (position_taken[first[i]]) {
      keep[i] = false;
      ++report.duplicate_points_dropped;
    } else {
      position_taken[first[i]] = true;
    }
  }
  std::size_t next = 0;
  for (std::size_t i = 0; i < cloud.positions.size(); ++i) {
    if (!keep[i]) continue;
    cloud.positions[next] = cloud.positions[i];
    if (with_normals) cloud.normals[next] = cloud.normals[i];
    ++next;
  }
  cloud.positions.resize(next);
  if (with_normals) cloud.normals.resize(next);

  report.welded_vertices = next;
  report.vertices = next;
  report.bounds = cloud.bounds();
  return report;
}

nlohmann::json to_json(const CleaningReport& report) {
  if (report.point_cloud) {
    return {{"kind", "point_cloud"},
            {"input_points", report.input_vertices},
            {"points", report.vertices},
            {"duplicate_points_dropped", report.duplicate_points_dropped},
            {"invalid_normals_dropped", report.invalid_normals_dropped},
            {"bounds", bounds_json(report.bounds)}};
  }
  return {{"kind", "mesh"},
          {"input_vertices", report.input_vertices},
          {"input_triangles", report.input_triangles},
          {"welded_vertices", report.welded_vertices},
          {"vertices", report.vertices},
          {"triangles", report.triangles},
          {"degenerate_dropped", report.degenerate_dropped},
          {"duplicate_triangles", report.duplicate_triangles},
          {"non_manifold_edges", report.non_manifold_edges},
          {"boundary_edges", report.boundary_edges},
          {"inconsistent_edges", report.inconsistent_edges},
          {"components", report.components},
          {"closed_and_oriented", report.closed_and_oriented},
          {"t_junctions_split", report.t_junctions_split},
          {"bounds", bounds_json(report.bounds)}};
}

}  // namespace dg
