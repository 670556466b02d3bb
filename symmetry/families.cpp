#include "symmetry/families.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dg {
namespace {

// Generator power k >= 1 with member ~ generator^k (compared by where both move `centre` and
// by rotation), or 0 when there is none up to max_power.
int power_of(const RigidTransform& generator, const RigidTransform& member, const Vec3& centre, double eps, int max_power) {
  RigidTransform power = generator;
  for (int k = 1; k <= max_power; ++k) {
    for (const RigidTransform& candidate : {power, power.inverse()})
      if (same_motion(candidate, member, centre, eps)) return k;
    power = generator.after(power);
  }
  return 0;
}

// How big a motion is, to pick the smallest as generator: angle first, then distance moved.
double magnitude(const RigidTransform& t, const Vec3& centre, double eps) {
  return t.angle() * 1e6 + (t.apply(centre) - centre).norm() / std::max(eps, 1e-300);
}

}  // namespace

std::vector<SymmetryFamily> group_families(const std::vector<RigidTransform>& motions, const std::vector<std::string>& kinds,
                                           const std::vector<char>& repeats, const Vec3& centre, double eps) {
  std::vector<std::size_t> order(motions.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return magnitude(motions[a], centre, eps) < magnitude(motions[b], centre, eps);
  });
  std::vector<bool> assigned(motions.size(), false);
  std::vector<SymmetryFamily> families;
  constexpr int max_power = 64;
  for (std::size_t g : order) {
    if (assigned[g]) continue;
    SymmetryFamily family;
    family.generator = motions[g];
    family.kind = kinds[g];
    for (std::size_t m : order) {
      if (assigned[m] || kinds[m] != kinds[g]) continue;
      const int k = m == g ? 1 : power_of(motions[g], motions[m], centre, eps, max_power);
      if (k == 0) continue;
      assigned[m] = true;
      family.members.push_back(m);
      family.powers.push_back(k);
    }
    std::vector<int> powers;
    for (std::size_t m = 0; m < family.members.size(); ++m)
      if (repeats[family.members[m]]) powers.push_back(family.powers[m]);
    if (family.kind == "rotation") {
      const double steps = 2.0 * std::numbers::pi / family.generator.angle();
      if (std::abs(steps - std::round(steps)) < 0.01 * steps) {
        family.order = static_cast<int>(std::lround(steps));
        for (std::size_t k = 0, found = powers.size(); k < found; ++k)
          if (family.order - powers[k] >= 1) powers.push_back(family.order - powers[k]);
      }
    }
    std::sort(powers.begin(), powers.end());
    powers.erase(std::unique(powers.begin(), powers.end()), powers.end());
    while (family.count < powers.size() && powers[family.count] == static_cast<int>(family.count) + 1) ++family.count;
    families.push_back(std::move(family));
  }
  // Report families in the order of their first member in the input.
  std::stable_sort(families.begin(), families.end(), [](const SymmetryFamily& a, const SymmetryFamily& b) {
    return *std::min_element(a.members.begin(), a.members.end()) < *std::min_element(b.members.begin(), b.members.end());
  });
  return families;
}

}  // namespace dg
