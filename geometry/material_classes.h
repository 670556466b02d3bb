#pragma once
// Materials that symmetry matching treats as one: a building whose windows take one of several
// glass tints at random repeats its windows, though no two tinted windows carry the same material.

#include "geometry/mesh.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace dg {

/// Whether `name` matches `pattern`, where '*' in the pattern stands for any run of characters
/// (possibly empty) and every other character for itself (case-sensitive).
bool matches_material_pattern(std::string_view name, std::string_view pattern);

/// The matching class of each material (indexed like `materials`): the lowest material index of
/// its group, or its own index when no group names it. A group is a comma-separated list
/// of names or '*' patterns, such as "glas*,jalousie1". Throws InputError naming the group and the
/// model's materials when a name or pattern matches no material, or when a material falls in two
/// groups.
std::vector<std::uint32_t> material_classes(const std::vector<Material>& materials,
                                            const std::vector<std::string>& groups);

}  // namespace dg
