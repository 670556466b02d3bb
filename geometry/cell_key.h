#pragma once
// Integer cells of a uniform 3D grid, for spatial hashing of points.

#include "geometry/types.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace dg {

using CellKey = std::array<std::int64_t, 3>;

/// The cell of edge length `cell` (model units) holding p: floor(p / cell) per axis.
inline CellKey cell_key(const Vec3& p, double cell) {
  return {static_cast<std::int64_t>(std::floor(p.x() / cell)), static_cast<std::int64_t>(std::floor(p.y() / cell)),
          static_cast<std::int64_t>(std::floor(p.z() / cell))};
}

/// Hash of a cell key, in unsigned arithmetic (far cells wrap instead of overflowing).
struct CellKeyHash {
  std::size_t operator()(const CellKey& k) const {
    return static_cast<std::size_t>(k[0]) * 73856093u ^ static_cast<std::size_t>(k[1]) * 19349663u ^
           static_cast<std::size_t>(k[2]) * 83492791u;
  }
};

}  // namespace dg
