#include "assets/generator/box_solid.h"

#include "assets/generator/mesh_builder.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace dg::assets {

namespace {

/// Sorted distinct coordinates; values within `tolerance` of the previous kept one merge into it.
std::vector<double> merged_lines(std::vector<double> values, double tolerance) {
  std::sort(values.begin(), values.end());
  std::vector<double> lines;
  for (double v : values) {
    if (lines.empty() || v - lines.back() > tolerance) lines.push_back(v);
  }
  return lines;
}

/// Index of the line that `value` was merged into.
std::size_t line_index(const std::vector<double>& lines, double value, double tolerance) {
  auto it = std::lower_bound(lines.begin(), lines.end(), value - tolerance);
  if (it == lines.end() || std::abs(*it - value) > tolerance) throw std::logic_error("box_solid: lost a coordinate");
  return static_cast<std::size_t>(it - lines.begin());
}

/// Lines refined `detail` times: interval i of `lines` becomes fine intervals i*detail ...
std::vector<double> refined_lines(const std::vector<double>& lines, int detail) {
  std::vector<double> fine;
  for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
    for (int s = 0; s < detail; ++s) fine.push_back(lines[i] + (lines[i + 1] - lines[i]) * s / detail);
  }
  fine.push_back(lines.back());
  return fine;
}

}  // namespace

void add_box(BoxSolid& solid, const Vec3& min, const Vec3& max) { solid.ops.push_back({min, max, false}); }

void subtract_box(BoxSolid& solid, const Vec3& min, const Vec3& max) { solid.ops.push_back({min, max, true}); }

void add_seam(BoxSolid& solid, int axis, double value) { solid.seams[static_cast<std::size_t>(axis)].push_back(value); }

TriangleMesh box_solid_surface(const BoxSolid& solid, int detail) {
  if (solid.ops.empty()) return {};
  BoundingBox extent;
  for (const BoxOp& op : solid.ops) {
    extent.add(op.min);
    extent.add(op.max);
  }
  const double tolerance = 1e-9 * std::max(1.0, extent.size().cwiseAbs().maxCoeff() +
                                                     extent.min.cwiseAbs().maxCoeff());

  std::array<std::vector<double>, 3> lines;
  std::array<std::vector<double>, 3> fine;
  std::array<std::size_t, 3> cells{};
  for (std::size_t axis = 0; axis < 3; ++axis) {
    std::vector<double> values = solid.seams[axis];
    for (const BoxOp& op : solid.ops) {
      values.push_back(op.min[static_cast<int>(axis)]);
      values.push_back(op.max[static_cast<int>(axis)]);
    }
    lines[axis] = merged_lines(std::move(values), tolerance);
    fine[axis] = refined_lines(lines[axis], detail);
    cells[axis] = lines[axis].size() - 1;
  }

  // Occupancy of the grid cells after applying the operations in order.
  std::vector<std::uint8_t> occupied(cells[0] * cells[1] * cells[2], 0);
  const auto cell = [&](std::size_t i, std::size_t j, std::size_t k) -> std::uint8_t& {
    return occupied[(k * cells[1] + j) * cells[0] + i];
  };
  for (const BoxOp& op : solid.ops) {
    std::array<std::size_t, 3> lo{}, hi{};
    for (std::size_t axis = 0; axis < 3; ++axis) {
      lo[axis] = line_index(lines[axis], op.min[static_cast<int>(axis)], tolerance);
      hi[axis] = line_index(lines[axis], op.max[static_cast<int>(axis)], tolerance);
    }
    for (std::size_t k = lo[2]; k < hi[2]; ++k)
      for (std::size_t j = lo[1]; j < hi[1]; ++j)
        for (std::size_t i = lo[0]; i < hi[0]; ++i) cell(i, j, k) = op.subtract ? 0 : 1;
  }

  // Every grid face between an occupied and an empty cell (or the outside) is on the surface.
  MeshBuilder builder;
  const auto d = static_cast<std::size_t>(detail);
  for (std::size_t a = 0; a < 3; ++a) {
    const std::size_t b = (a + 1) % 3, c = (a + 2) % 3;  // (e_b, e_c, e_a) is right-handed
    const auto occupied_at = [&](std::size_t ia, std::size_t ib, std::size_t ic) -> bool {
      std::array<std::size_t, 3> index{};
      index[a] = ia;
      index[b] = ib;
      index[c] = ic;
      return cell(index[0], index[1], index[2]) != 0;
    };
    const auto point = [&](std::size_t fa, std::size_t fb, std::size_t fc) {
      Vec3 p;
      p[static_cast<int>(a)] = fine[a][fa];
      p[static_cast<int>(b)] = fine[b][fb];
      p[static_cast<int>(c)] = fine[c][fc];
      return p;
    };
    for (std::size_t ia = 0; ia <= cells[a]; ++ia) {
      for (std::size_t ic = 0; ic < cells[c]; ++ic) {
        for (std::size_t ib = 0; ib < cells[b]; ++ib) {
          const bool below = ia > 0 && occupied_at(ia - 1, ib, ic);
          const bool above = ia < cells[a] && occupied_at(ia, ib, ic);
          if (below == above) continue;
          const std::size_t fa = ia * d;
          for (std::size_t t = 0; t < d; ++t) {
            for (std::size_t s = 0; s < d; ++s) {
              const std::size_t fb = ib * d + s, fc = ic * d + t;
              const Vec3 p00 = point(fa, fb, fc), p10 = point(fa, fb + 1, fc);
              const Vec3 p11 = point(fa, fb + 1, fc + 1), p01 = point(fa, fb, fc + 1);
              if (below) {
                builder.quad(p00, p10, p11, p01);  // normal +a
              } else {
                builder.quad(p00, p01, p11, p10);  // normal -a
              }
            }
          }
        }
      }
    }
  }
  return builder.take();
}

}  // namespace dg::assets
