#pragma once
// Points drawn on a mesh's surface: scan-like point clouds with a known surface behind them.

#include "geometry/mesh.h"

#include <cstddef>
#include <cstdint>

namespace dg {

/// `count` points drawn area-uniformly on the triangles of `mesh` (seeded: the same seed gives
/// the same points), each with its triangle's unit normal. Degenerate triangles get no points;
/// a mesh without area gives an empty cloud.
PointCloud sample_surface(const TriangleMesh& mesh, std::size_t count, std::uint64_t seed);

/// Moves every point of `cloud` by an independent Gaussian offset of standard deviation `sigma`
/// (model units) per axis, like scanner noise (seeded); normals stay as they are.
void add_noise(PointCloud& cloud, double sigma, std::uint64_t seed);

}  // namespace dg
