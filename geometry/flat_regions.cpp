#include "geometry/flat_regions.h"

#include "geometry/flat_faces.h"
#include "geometry/segment_index.h"
#include "geometry/union_find.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <utility>

namespace dg {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
using Edge = std::pair<std::uint32_t, std::uint32_t>;  // vertex indices, lower first

// A flat face being gathered: its triangles, summed area vector and outline edges.
struct Face {
  std::vector<std::uint32_t> triangles;
  Vec3 area_vector = Vec3::Zero();
  std::vector<Edge> outline;
};

// Edges that an odd number of the listed triangles use.
std::vector<Edge> odd_edges(const TriangleMesh& mesh, const std::vector<std::uint32_t>& triangles) {
  std::map<Edge, int> uses;
  for (std::uint32_t t : triangles)
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3])];
  std::vector<Edge> odd;
  for (const auto& [edge, count] : uses)
    if (count % 2 == 1) odd.push_back(edge);
  return odd;
}

// Whether every end of `edges` lies within `tolerance` of the plane through `origin` with unit
// normal `normal`.
bool on_plane(const TriangleMesh& mesh, const std::vector<Edge>& edges, const Vec3& origin, const Vec3& normal, double tolerance) {
  return std::all_of(edges.begin(), edges.end(), [&](const Edge& e) {
    return std::abs(normal.dot(mesh.positions[e.first] - origin)) <= tolerance &&
           std::abs(normal.dot(mesh.positions[e.second] - origin)) <= tolerance;
  });
}

// `edges` split at every one of their ends that lies within `tolerance` of another edge, strictly
// between its ends (a T-junction), without the parts used an even number of times.
std::vector<Edge> union_outline(const TriangleMesh& mesh, const std::vector<Edge>& edges, double tolerance) {
  // The ends by x, so each edge examines only those within its x range.
  std::vector<std::uint32_t> ends;
  for (const Edge& e : edges) ends.push_back(e.first), ends.push_back(e.second);
  std::sort(ends.begin(), ends.end());
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
  std::vector<std::pair<double, std::uint32_t>> by_x;
  for (std::uint32_t v : ends) by_x.emplace_back(mesh.positions[v].x(), v);
  std::sort(by_x.begin(), by_x.end());
  std::map<Edge, int> uses;
  for (const Edge& e : edges) {
    const Vec3 from = mesh.positions[e.first], along = mesh.positions[e.second] - from;
    const double length2 = along.squaredNorm();
    std::vector<std::pair<double, std::uint32_t>> inner;
    const double low = std::min(from.x(), from.x() + along.x()) - tolerance;
    const double high = std::max(from.x(), from.x() + along.x()) + tolerance;
    if (length2 > 0.0)
      for (auto it = std::lower_bound(by_x.begin(), by_x.end(), std::pair{low, std::uint32_t{0}});
           it != by_x.end() && it->first <= high; ++it) {
        const std::uint32_t v = it->second;
        if (v == e.first || v == e.second) continue;
        const Vec3 offset = mesh.positions[v] - from;
        const double s = offset.dot(along) / length2;
        if (s > 0.0 && s < 1.0 && (offset - s * along).norm() <= tolerance) inner.emplace_back(s, v);
      }
    std::sort(inner.begin(), inner.end());
    std::uint32_t previous = e.first;
    for (const auto& [s, v] : inner) ++uses[std::minmax(previous, v)], previous = v;
    ++uses[std::minmax(previous, e.second)];
  }
  std::vector<Edge> outline;
  for (const auto& [edge, count] : uses)
    if (count % 2 == 1) outline.push_back(edge);
  return outline;
}

// Points of `segment` every `spacing` (model units) at most, both ends included.
std::vector<Vec3> points_along(const Segment& segment, double spacing) {
  const Vec3 along = segment[1] - segment[0];
  const int steps = std::max(1, static_cast<int>(std::ceil(along.norm() / spacing)));
  std::vector<Vec3> points;
  for (int i = 0; i <= steps; ++i) points.push_back(segment[0] + (static_cast<double>(i) / steps) * along);
  return points;
}

// Whether every point of `from` (sampled every distance / 4) lies within `distance` (model units)
// of a segment of `to`. Each point tries first the segment of `to` the point before it was near
// (neighbouring points nearly always share one), then all of them; a point near none ends the
// test there.
bool outline_within(const std::vector<Segment>& from, const std::vector<Segment>& to, double distance) {
  std::size_t last = 0;
  auto near_segment = [&](const Vec3& p, std::size_t i) { return (closest_point_on_segment(p, to[i]) - p).norm() <= distance; };
  auto near = [&](const Vec3& p) {
    if (to.empty()) return false;
    if (near_segment(p, last)) return true;
    for (std::size_t i = 0; i < to.size(); ++i)
      if (i != last && near_segment(p, i)) {
        last = i;
        return true;
      }
    return false;
  };
  return std::all_of(from.begin(), from.end(), [&](const Segment& segment) {
    const std::vector<Vec3> points = points_along(segment, 0.25 * distance);
    return std::all_of(points.begin(), points.end(), near);
  });
}

}  // namespace

std::vector<FlatRegion> flat_regions(const TriangleMesh& mesh, const std::vector<char>& wanted, FlatJoin join) {
  if (mesh.triangles.empty()) return {};
  const double tolerance = kFlatFraction * mesh.bounds().diagonal();
  const std::vector<std::uint32_t> face_of = flat_faces(mesh, {}, tolerance);
  std::vector<std::uint32_t> slot(mesh.triangles.size(), kNone);  // per face id (a triangle index)
  std::vector<Face> faces;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    if (wanted[t] && slot[face_of[t]] == kNone) slot[face_of[t]] = static_cast<std::uint32_t>(faces.size()), faces.emplace_back();
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    if (slot[face_of[t]] != kNone) {
      Face& f = faces[slot[face_of[t]]];
      f.triangles.push_back(t);
      f.area_vector += mesh.area_vector(t);
    }
  for (Face& f : faces) f.outline = odd_edges(mesh, f.triangles);
  auto material = [&](const Face& f) { return mesh.has_materials() ? mesh.materials[f.triangles.front()] : 0u; };
  // Faces of one material, facing the same side, each one's outline on the other's plane.
  std::vector<std::uint32_t> region(faces.size());
  std::iota(region.begin(), region.end(), 0u);
  auto coplanar = [&](const Face& f, const Face& g) {
    const Vec3 normal = f.area_vector.normalized();
    return !f.outline.empty() && on_plane(mesh, g.outline, mesh.positions[f.outline.front().first], normal, tolerance);
  };
  auto join_if_one = [&](std::uint32_t i, std::uint32_t j) {
    if (find_root(region, i) != find_root(region, j) && material(faces[i]) == material(faces[j]) &&
        faces[i].area_vector.dot(faces[j].area_vector) > 0.0 && coplanar(faces[i], faces[j]) && coplanar(faces[j], faces[i]))
      region[find_root(region, j)] = find_root(region, i);
  };
  if (join == FlatJoin::coplanar) {
    for (std::uint32_t i = 0; i < faces.size(); ++i)
      for (std::uint32_t j = i + 1; j < faces.size(); ++j) join_if_one(i, j);
  } else {
    // Only faces with a corner of their outlines in common may join: the pairs around each corner.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> at_corner;  // (corner, face)
    for (std::uint32_t i = 0; i < faces.size(); ++i)
      for (const Edge& e : faces[i].outline) at_corner.insert(at_corner.end(), {{e.first, i}, {e.second, i}});
    std::sort(at_corner.begin(), at_corner.end());
    at_corner.erase(std::unique(at_corner.begin(), at_corner.end()), at_corner.end());
    for (std::size_t begin = 0; begin < at_corner.size();) {
      std::size_t end = begin + 1;
      while (end < at_corner.size() && at_corner[end].first == at_corner[begin].first) ++end;
      for (std::size_t a = begin; a < end; ++a)
        for (std::size_t b = a + 1; b < end; ++b) join_if_one(at_corner[a].second, at_corner[b].second);
      begin = end;
    }
  }
  std::vector<FlatRegion> regions;
  std::vector<std::uint32_t> region_slot(faces.size(), kNone);
  std::vector<std::vector<Edge>> edges;
  std::vector<Vec3> area_vectors;
  for (std::uint32_t i = 0; i < faces.size(); ++i) {
    const std::uint32_t r = find_root(region, i);
    if (region_slot[r] == kNone) {
      region_slot[r] = static_cast<std::uint32_t>(regions.size());
      regions.emplace_back();
      regions.back().material = material(faces[i]);
      edges.emplace_back();
      area_vectors.push_back(Vec3::Zero());
    }
    const std::uint32_t k = region_slot[r];
    FlatRegion& out = regions[k];
    out.triangles.insert(out.triangles.end(), faces[i].triangles.begin(), faces[i].triangles.end());
    edges[k].insert(edges[k].end(), faces[i].outline.begin(), faces[i].outline.end());
    area_vectors[k] += faces[i].area_vector;
  }
  for (std::size_t k = 0; k < regions.size(); ++k) {
    FlatRegion& out = regions[k];
    std::sort(out.triangles.begin(), out.triangles.end());
    out.normal = area_vectors[k].normalized();
    for (std::uint32_t t : out.triangles) {
      out.area += 0.5 * mesh.area_vector(t).norm();
      for (std::uint32_t v : mesh.triangles[t]) out.bounds.add(mesh.positions[v]);
    }
    for (const Edge& e : union_outline(mesh, edges[k], tolerance))
      out.outline.push_back({mesh.positions[e.first], mesh.positions[e.second]});
  }
  return regions;
}

FlatRegion moved_region(const FlatRegion& region, const TriangleMesh& mesh, const RigidTransform& motion) {
  FlatRegion moved = region;
  moved.normal = motion.apply_direction(region.normal);
  moved.bounds = BoundingBox{};
  for (std::uint32_t t : region.triangles)
    for (std::uint32_t v : mesh.triangles[t]) moved.bounds.add(motion.apply(mesh.positions[v]));
  for (Segment& s : moved.outline) s = {motion.apply(s[0]), motion.apply(s[1])};
  return moved;
}

bool same_flat_region(const FlatRegion& x, const FlatRegion& y, double distance) {
  if (x.material != y.material || !(x.normal.dot(y.normal) > 0.0) || x.outline.empty() || y.outline.empty() ||
      (x.bounds.min - y.bounds.min).norm() > distance || (x.bounds.max - y.bounds.max).norm() > distance)
    return false;
  if (std::abs(x.area - y.area) > distance * std::max(curve_length(x.outline), curve_length(y.outline))) return false;
  auto on_plane_of = [&](const FlatRegion& f, const FlatRegion& plane) {
    const Vec3& origin = plane.outline.front()[0];
    return std::all_of(f.outline.begin(), f.outline.end(), [&](const Segment& s) {
      return std::abs(plane.normal.dot(s[0] - origin)) <= distance && std::abs(plane.normal.dot(s[1] - origin)) <= distance;
    });
  };
  return on_plane_of(x, y) && on_plane_of(y, x) && outline_within(x.outline, y.outline, distance) &&
         outline_within(y.outline, x.outline, distance);
}

}  // namespace dg
