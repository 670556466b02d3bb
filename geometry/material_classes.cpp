#include "geometry/material_classes.h"

#include "geometry/errors.h"

#include <algorithm>
#include <numeric>

namespace dg {
namespace {

std::string listed_names(const std::vector<Material>& materials) {
  std::string names;
  for (const Material& material : materials) names += (names.empty() ? "" : ", ") + material.name;
  return names.empty() ? std::string("none") : names;
}

std::vector<std::string_view> split_group(std::string_view group) {
  std::vector<std::string_view> parts;
  while (true) {
    const std::size_t comma = group.find(',');
    std::string_view part = group.substr(0, comma);
    while (!part.empty() && part.front() == ' ') part.remove_prefix(1);
    while (!part.empty() && part.back() == ' ') part.remove_suffix(1);
    if (!part.empty()) parts.push_back(part);
    if (comma == std::string_view::npos) return parts;
    group.remove_prefix(comma + 1);
  }
}

}  // namespace

bool matches_material_pattern(std::string_view name, std::string_view pattern) {
  // Greedy wildcard match with backtracking to the last '*'.
  std::size_t n = 0, p = 0, star = std::string_view::npos, resume = 0;
  while (n < name.size()) {
    if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      resume = n;
    } else if (p < pattern.size() && pattern[p] == name[n]) {
      ++p;
      ++n;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      n = ++resume;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

std::vector<std::uint32_t> material_classes(const std::vector<Material>& materials,
                                            const std::vector<std::string>& groups) {
  std::vector<std::uint32_t> classes(materials.size());
  std::iota(classes.begin(), classes.end(), std::uint32_t{0});
  std::vector<const std::string*> group_of(materials.size(), nullptr);
  for (const std::string& group : groups) {
    const std::vector<std::string_view> parts = split_group(group);
    if (parts.empty()) throw InputError("--same-material '" + group + "' names no material");
    std::vector<std::uint32_t> members;
    for (std::string_view part : parts) {
      bool matched = false;
      for (std::size_t m = 0; m < materials.size(); ++m) {
        if (!matches_material_pattern(materials[m].name, part)) continue;
        matched = true;
        if (group_of[m] && group_of[m] != &group)
          throw InputError("material '" + materials[m].name + "' is in two --same-material groups: '" + *group_of[m] +
                           "' and '" + group + "'");
        group_of[m] = &group;
        members.push_back(static_cast<std::uint32_t>(m));
      }
      if (!matched)
        throw InputError("--same-material '" + group + "': no material matches '" + std::string(part) +
                         "' (the model's materials: " + listed_names(materials) + ")");
    }
    const std::uint32_t shared = *std::min_element(members.begin(), members.end());
    for (std::uint32_t m : members) classes[m] = shared;
  }
  return classes;
}

}  // namespace dg
