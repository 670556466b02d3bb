#include "geometry/surface_sampling.h"

#include "geometry/random.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dg {

PointCloud sample_surface(const TriangleMesh& mesh, std::size_t count, std::uint64_t seed) {
  std::vector<double> cumulative;
  cumulative.reserve(mesh.triangles.size());
  double total = 0.0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) cumulative.push_back(total += mesh.area_vector(t).norm());
  PointCloud cloud;
  if (!(total > 0.0)) return cloud;
  cloud.positions.reserve(count);
  cloud.normals.reserve(count);
  Random random(seed);
  for (std::size_t i = 0; i < count; ++i) {
    const double pick = random.uniform() * total;
    const auto t = static_cast<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin());
    const std::size_t triangle = std::min(t, mesh.triangles.size() - 1);
    // sqrt of the first number makes the barycentric draw uniform over the triangle's area.
    const double s = std::sqrt(random.uniform()), u = random.uniform();
    const auto [a, b, c] = mesh.corners(triangle);
    cloud.positions.push_back((1.0 - s) * a + s * (1.0 - u) * b + s * u * c);
    cloud.normals.push_back(mesh.area_vector(triangle).normalized());
  }
  return cloud;
}

void add_noise(PointCloud& cloud, double sigma, std::uint64_t seed) {
  Random random(seed);
  // Box-Muller: two uniform numbers give one standard normal number.
  auto normal = [&] {
    const double u = 1.0 - random.uniform(), v = random.uniform();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
  };
  for (Vec3& p : cloud.positions)
    for (int axis = 0; axis < 3; ++axis) p[axis] += sigma * normal();
}

}  // namespace dg
