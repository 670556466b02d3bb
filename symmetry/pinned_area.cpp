#include "symmetry/pinned_area.h"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace dg {

RigidTransform fractional_power(const RigidTransform& t, double s) {
  const ScrewParameters screw = screw_parameters(t);
  RigidTransform power;
  power.rotation = Eigen::AngleAxisd(s * screw.angle, screw.axis).toRotationMatrix();
  power.translation = screw.axis_point - power.rotation * screw.axis_point + s * screw.slide * screw.axis;
  return power;
}

double pinned_area(const CellMatcher& matcher, const VoxelSurface& surface, const RigidTransform& t,
                   const std::vector<std::uint32_t>& region, double shift) {
  // Speed of each cell under t^s at s = 0 (model units per unit of s): t^s moves it about s times that.
  const ScrewParameters screw = screw_parameters(t);
  double fastest = 0.0;
  for (std::uint32_t c : region)
    fastest = std::max(fastest, (screw.angle * screw.axis.cross(surface.centre(c) - screw.axis_point) + screw.slide * screw.axis).norm());
  if (region.empty() || !(fastest > 0.0)) return 0.0;
  const RigidTransform longer = t.after(fractional_power(t, shift / fastest));
  const RigidTransform inverse = longer.inverse();
  // An evenly strided sample of the region's cells, its pinned area scaled up to the region.
  constexpr std::size_t max_samples = 8192;
  const std::size_t stride = (region.size() + max_samples - 1) / max_samples;
  std::vector<char> pinned((region.size() + stride - 1) / stride, 0);
  tbb::parallel_for(std::size_t(0), pinned.size(),
                    [&](std::size_t i) { pinned[i] = matcher.symmetric(region[i * stride], longer, inverse) ? 0 : 1; });
  double sampled = 0.0, pinned_sampled = 0.0, total = 0.0;  // summed in cell order: deterministic
  for (std::size_t i = 0; i < pinned.size(); ++i) {
    sampled += surface.area(region[i * stride]);
    pinned_sampled += pinned[i] ? surface.area(region[i * stride]) : 0.0;
  }
  for (std::uint32_t c : region) total += surface.area(c);
  return sampled > 0.0 ? total * pinned_sampled / sampled : 0.0;
}

}  // namespace dg
