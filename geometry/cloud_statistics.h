#pragma once
// Sampling statistics of a point cloud: how far apart its points lie (how large a disk each
// point must stand for so that the disks cover the surface between them) and how far they
// scatter off the surface (scanner noise).

#include "geometry/mesh.h"

#include <cstddef>

namespace dg {

/// The median, over up to `probes` points picked evenly through the cloud, of the distance to
/// the k-th nearest other point, capped at `max_distance` (model units; points with fewer than
/// k others within it count as the cap): how far apart the points lie. Throws InputError for an empty cloud or a non-positive cap.
double typical_point_spacing(const PointCloud& cloud, double max_distance, std::size_t k = 4,
                             std::size_t probes = 4000);

/// The scatter of points off flat surface: over up to `probes` points picked evenly through the
/// cloud that have at least 10 others within `radius` (model units), the root-mean-square
/// distance of those points to their least-squares plane, the median over the probes (most
/// probes of a built model lie on flat parts; creases give larger values). 0 when no probe has
/// enough neighbours. Throws InputError for an empty cloud or a non-positive radius.
double typical_point_noise(const PointCloud& cloud, double radius, std::size_t probes = 4000);

}  // namespace dg
