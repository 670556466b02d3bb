#pragma once
// Sampling statistics of a point cloud: how far apart its points lie (how large a disk each
// point must stand for so that the disks cover the surface between them) and how far they
// scatter off the surface (scanner noise).

#include "geometry/mesh.h"

#include <cstddef>

namespace dg {

struct PointStatistics {
  /// The median distance to the 4th nearest other point (points with fewer than 4 others within
  /// the radius count as the radius): how far apart the points lie. Model units.
  double spacing = 0.0;
  /// The median, over points with at least 10 others within the radius, of the root-mean-square
  /// distance of those points to their least-squares plane (most probes of a built model lie on
  /// flat parts; creases give larger values); 0 when no probe has that many. Model units.
  double noise = 0.0;
  /// The same within twice the radius: scanner noise reads about as `noise` there, surface
  /// detail (bends, relief) more. Model units.
  double noise_wide = 0.0;
};

/// The statistics over up to `probes` points picked evenly through the cloud, from their
/// neighbours within `radius` (model units; noise_wide within twice it), in one pass. Throws InputError for an empty cloud
/// or a non-positive radius.
PointStatistics point_statistics(const PointCloud& cloud, double radius, std::size_t probes = 4000);

}  // namespace dg
