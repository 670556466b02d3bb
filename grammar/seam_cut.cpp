#include "grammar/seam_cut.h"

#include "grammar/cell_sets.h"
#include "symmetry/symmetric_region.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dg {

SeamSurface voxel_seam(const VoxelSurface& surface, const std::vector<std::uint32_t>& site,
                       const std::vector<std::uint32_t>& docker, std::vector<char>& docker_side) {
  docker_side = mask_of(docker, surface.cell_count());
  std::vector<std::uint32_t> inner_band;
  for (std::uint32_t c : site) {
    const auto n = surface.neighbours(c);
    if (std::any_of(n.begin(), n.end(), [&](std::uint32_t m) { return docker_side[m] != 0; })) inner_band.push_back(c);
  }
  for (std::uint32_t c : inner_band) docker_side[c] = 1;
  SeamSurface seam;
  seam.kind = SeamSurface::Kind::voxel_faces;
  seam.eps = surface.eps();
  for (std::uint32_t c : inner_band) {
    const VoxelCoord& v = surface.coord(c);
    for (int axis = 0; axis < 3; ++axis)
      for (int step : {-1, 1}) {
        VoxelCoord w = v;
        w[axis] += step;
        const std::int64_t other = surface.find(w);
        if (other >= 0 && docker_side[static_cast<std::uint32_t>(other)]) continue;
        VoxelFace face;
        face.axis = axis;
        face.voxel = step < 0 ? v : w;  // the face is the lower side of the upper voxel
        seam.faces.push_back(face);
      }
  }
  std::sort(seam.faces.begin(), seam.faces.end());
  seam.faces.erase(std::unique(seam.faces.begin(), seam.faces.end()), seam.faces.end());
  return seam;
}

std::vector<PlaneFamily> seam_planes(const SeamSurface& seam, const RigidTransform& frame) {
  if (seam.kind == SeamSurface::Kind::plane) {
    const Vec3 n = frame.apply_direction(seam.normal);
    return {{n, {n.dot(frame.apply(seam.offset * seam.normal))}}};
  }
  std::vector<PlaneFamily> families;
  if (seam.faces.empty()) return families;
  for (int axis = 0; axis < 3; ++axis) {
    std::int32_t first = std::numeric_limits<std::int32_t>::max(), last = std::numeric_limits<std::int32_t>::min();
    for (const VoxelFace& f : seam.faces) {
      first = std::min(first, f.voxel[axis]);
      last = std::max(last, f.voxel[axis] + (f.axis == axis ? 0 : 1));
    }
    PlaneFamily family;
    family.direction = frame.rotation.col(axis);
    const double base = family.direction.dot(frame.translation);
    for (std::int32_t k = first - 1; k <= last + 1; ++k) family.offsets.push_back(base + static_cast<double>(k) * seam.eps);
    families.push_back(std::move(family));
  }
  return families;
}

SeamFaceIndex::SeamFaceIndex(const SeamSurface& seam) : eps_(seam.eps) {
  keys_.reserve(seam.faces.size());
  for (const VoxelFace& f : seam.faces)
    keys_.push_back({f.axis, f.voxel[f.axis], f.voxel[(f.axis + 1) % 3], f.voxel[(f.axis + 2) % 3]});
  std::sort(keys_.begin(), keys_.end());
}

namespace {

using Point2 = std::array<double, 2>;

// Whether segment from-to meets the square [j, j+1] x [l, l+1] grown by `margin` on every side
// (grid units; Liang-Barsky clipping).
bool segment_meets_square(const Point2& from, const Point2& to, std::int64_t j, std::int64_t l, double margin) {
  const Point2 lo{static_cast<double>(j) - margin, static_cast<double>(l) - margin};
  double t0 = 0.0, t1 = 1.0;
  for (int d = 0; d < 2; ++d) {
    const double delta = to[d] - from[d], hi = lo[d] + 1.0 + 2.0 * margin;
    if (delta == 0.0) {
      if (from[d] < lo[d] || from[d] > hi) return false;
      continue;
    }
    double ta = (lo[d] - from[d]) / delta, tb = (hi - from[d]) / delta;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta), t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

bool crosses_face(const SeamFaceIndex& faces, const std::array<Vec3, 3>& corners, int axis, std::int32_t plane) {
  const int b = (axis + 1) % 3, c = (axis + 2) % 3;
  const double eps = faces.eps(), level = plane * eps;
  // The chord: where the triangle meets the plane, in grid units of the other two axes.
  std::array<Point2, 3> ends;
  int count = 0;
  for (int k = 0; k < 3; ++k) {
    const Vec3 &p = corners[k], &q = corners[(k + 1) % 3];
    const double dp = p[axis] - level, dq = q[axis] - level;
    if (dp == 0.0) ends[count++] = {p[b] / eps, p[c] / eps};
    if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0)) {
      const Vec3 x = p + (dp / (dp - dq)) * (q - p);
      ends[count++] = {x[b] / eps, x[c] / eps};
    }
  }
  double lo_b = corners[0][b], hi_b = lo_b, lo_c = corners[0][c], hi_c = lo_c;
  for (const Vec3& p : corners) {
    lo_b = std::min(lo_b, p[b]), hi_b = std::max(hi_b, p[b]);
    lo_c = std::min(lo_c, p[c]), hi_c = std::max(hi_c, p[c]);
  }
  // Faces whose square [j, j+1] x [l, l+1] (times eps) meets the triangle's box, with a little
  // slack; of those, the ones the chord meets (all of them when rounding left no chord).
  const double slack = 1e-6;
  const auto j0 = static_cast<std::int64_t>(std::floor(lo_b / eps - slack)) - 1, j1 = static_cast<std::int64_t>(std::floor(hi_b / eps + slack));
  const auto l0 = static_cast<std::int64_t>(std::floor(lo_c / eps - slack)) - 1, l1 = static_cast<std::int64_t>(std::floor(hi_c / eps + slack));
  return faces.any_in(axis, plane, j0, j1, l0, l1, [&](std::int64_t j, std::int64_t l) {
    return count == 0 || segment_meets_square(ends[0], ends[count - 1], j, l, slack);
  });
}

bool on_docker_side(const SeamSurface& seam, const VoxelSurface& surface, const std::vector<char>& docker_side,
                    const RigidTransform& frame_inverse, const Vec3& p) {
  const Vec3 q = frame_inverse.apply(p);
  if (seam.kind == SeamSurface::Kind::plane) return seam.normal.dot(q) - seam.offset > 0.0;
  Vec3 centre;
  for (int axis = 0; axis < 3; ++axis) {
    const double g = q[axis] / seam.eps;
    const double below = std::abs(g - std::round(g)) <= 1e-6 ? std::round(g) - 1.0 : std::floor(g);
    centre[axis] = (below + 0.5) * seam.eps;
  }
  const std::int64_t cell = nearest_cell(surface, centre);
  return cell >= 0 && docker_side[static_cast<std::uint32_t>(cell)];
}

}  // namespace dg
