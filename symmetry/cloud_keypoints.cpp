#include "symmetry/cloud_keypoints.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

namespace dg {
namespace {

// Points of the voxels within two voxels of `voxel` (a 5x5x5 block).
std::vector<Vec3> nearby_points(const PointCloud& cloud, const VoxelSurface& surface, const VoxelCoord& voxel) {
  std::vector<Vec3> points;
  for (int dx = -2; dx <= 2; ++dx)
    for (int dy = -2; dy <= 2; ++dy)
      for (int dz = -2; dz <= 2; ++dz) {
        const std::int64_t c = surface.find({voxel[0] + dx, voxel[1] + dy, voxel[2] + dz});
        if (c < 0) continue;
        for (std::uint32_t p : surface.points(static_cast<std::uint32_t>(c))) points.push_back(cloud.positions[p]);
      }
  return points;
}

double distance(const CellPlane& plane, const Vec3& p) { return std::abs(plane.normal.dot(p) - plane.offset); }

// Where the half-plane of `plane` (the side of the crease it lies on) points, seen from the
// crease through `corner` with direction `tangent`: the unit in-plane direction orthogonal to
// the crease, from the points on `plane` but off `other` that lie along the crease on its
// tangent side within `reach`; zero when fewer than `min_points` do.
Vec3 half_plane_direction(const std::vector<Vec3>& points, const CellPlane& plane, const CellPlane& other, const Vec3& corner,
                          const Vec3& tangent, double tolerance, double reach, std::size_t min_points) {
  const Vec3 across = plane.normal.cross(tangent).normalized();
  double sum = 0.0;
  std::size_t count = 0;
  for (const Vec3& q : points) {
    const Vec3 d = q - corner;
    const double along = d.dot(tangent);
    if (along < 0.2 * reach || along > reach || distance(plane, q) >= tolerance || distance(other, q) < tolerance) continue;
    if ((d - along * tangent).norm() > reach) continue;
    sum += d.dot(across);
    ++count;
  }
  if (count < min_points || sum == 0.0) return Vec3::Zero();
  return sum > 0.0 ? across : Vec3(-across);
}

// The frame of a crease between planes a and b through `point` running along `tangent`, from the
// half-planes' directions (see half_plane_direction); empty when either shows no points there.
std::optional<Keypoint> crease_frame(const std::vector<Vec3>& points, const CellPlane& a, const CellPlane& b, const Vec3& point,
                                     const Vec3& tangent, double tolerance, double reach, std::size_t min_points) {
  const Vec3 wa = half_plane_direction(points, a, b, point, tangent, tolerance, reach, min_points);
  const Vec3 wb = half_plane_direction(points, b, a, point, tangent, tolerance, reach, min_points);
  if (wa.isZero() || wb.isZero()) return std::nullopt;
  const Vec3 normal = -(wa + wb).normalized();
  Keypoint frame{point, tangent, normal, tangent.cross(normal), {}};
  frame.descriptor.dihedral_degrees = std::acos(std::clamp(wa.dot(wb), -1.0, 1.0)) * 180.0 / std::numbers::pi;
  return frame;
}

}  // namespace

std::vector<Keypoint> cloud_keypoints(const PointCloud& cloud, const VoxelSurface& surface, const CloudKeypointOptions& options) {
  std::vector<Keypoint> keypoints;
  const double eps = surface.eps();
  const double tolerance = options.inlier_tolerance_eps * eps;
  const double reach = 1.8 * eps;  // stays inside the 5x5x5 block around the corner's voxel
  const double cos_same = std::cos(options.same_plane_degrees * std::numbers::pi / 180.0);
  std::vector<CellPlane> planes;
  for (std::uint32_t c = 0; c < surface.cell_count(); ++c) {
    // The planes of the cell and of its neighbours, one per surface (scan noise can leave a
    // corner's own cell with fewer than its three planes).
    planes.clear();
    auto add = [&](const CellPlane& plane) {
      for (const CellPlane& known : planes)
        if (std::abs(known.normal.dot(plane.normal)) > cos_same &&
            std::abs(known.offset - (known.normal.dot(plane.normal) > 0.0 ? plane.offset : -plane.offset)) < tolerance)
          return;
      planes.push_back(plane);
    };
    for (const CellPlane& plane : surface.planes(c)) add(plane);
    if (planes.size() < 2) continue;
    // A crease cell (two planes of its own) tries each plane of its neighbours as the third;
    // a corner cell uses its first three.
    const bool crease_cell = planes.size() == 2;
    if (crease_cell)
      for (std::uint32_t n : surface.neighbours(c))
        for (const CellPlane& plane : surface.planes(n)) add(plane);
    const std::size_t thirds_end = crease_cell ? planes.size() : 3;
    std::vector<Vec3> points;
    for (std::size_t k = 2; k < thirds_end; ++k) {
      const std::array<CellPlane, 3> corner_planes{planes[0], planes[1], planes[k]};
      Mat3 normals;
      Vec3 offsets;
      for (int i = 0; i < 3; ++i) normals.row(i) = corner_planes[i].normal.transpose(), offsets[i] = corner_planes[i].offset;
      if (std::abs(normals.determinant()) < options.min_corner_determinant) continue;
      const Vec3 corner = normals.partialPivLu().solve(offsets);
      if (surface.voxel_of(corner) != surface.coord(c)) continue;  // each corner once, from its own voxel
      if (points.empty()) points = nearby_points(cloud, surface, surface.coord(c));
      for (std::size_t a = 0; a < 3; ++a)
        for (std::size_t b = a + 1; b < 3; ++b) {
          const CellPlane &pa = corner_planes[a], &pb = corner_planes[b];
          const Vec3 direction = pa.normal.cross(pb.normal).normalized();
          Keypoint found{};
          int sides = 0;
          for (const Vec3& tangent : {direction, Vec3(-direction)})
            if (const auto frame = crease_frame(points, pa, pb, corner, tangent, tolerance, reach, options.min_side_points)) {
              ++sides;
              found = *frame;
            }
          if (sides == 1) keypoints.push_back(found);
        }
    }
  }
  return keypoints;
}

std::vector<Keypoint> cloud_crease_samples(const PointCloud& cloud, const VoxelSurface& surface, const CloudKeypointOptions& options,
                                           double min_crease_angle_degrees) {
  std::vector<Keypoint> samples;
  const double eps = surface.eps();
  const double tolerance = options.inlier_tolerance_eps * eps;
  const double reach = 1.8 * eps;
  const double max_cos = std::cos(min_crease_angle_degrees * std::numbers::pi / 180.0);
  for (std::uint32_t c = 0; c < surface.cell_count(); ++c) {
    const auto planes = surface.planes(c);
    if (planes.size() < 2) continue;
    std::vector<Vec3> points;
    for (std::size_t a = 0; a < planes.size(); ++a)
      for (std::size_t b = a + 1; b < planes.size(); ++b) {
        if (std::abs(planes[a].normal.dot(planes[b].normal)) > max_cos) continue;
        const Vec3 direction = planes[a].normal.cross(planes[b].normal).normalized();
        // The line's point nearest the voxel centre: both plane equations, and no step along it.
        Mat3 system;
        system.row(0) = planes[a].normal.transpose();
        system.row(1) = planes[b].normal.transpose();
        system.row(2) = direction.transpose();
        const Vec3 centre = surface.centre(c);
        const Vec3 point = system.partialPivLu().solve(Vec3(planes[a].offset, planes[b].offset, direction.dot(centre)));
        if (surface.voxel_of(point) != surface.coord(c)) continue;
        if (points.empty()) points = nearby_points(cloud, surface, surface.coord(c));
        if (const auto frame = crease_frame(points, planes[a], planes[b], point, direction, tolerance, reach, options.min_side_points))
          samples.push_back(*frame);
      }
  }
  return samples;
}

}  // namespace dg
