#include "grammar/grid_rules.h"

#include "grammar/grid_direction.h"
#include "grammar/whole_parts.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <optional>

namespace dg {
namespace {

// Distance of a unit direction from the span of others above which it counts as independent
// (about 1 degree).
constexpr double kIndependentDirection = 0.02;

// Whether t leaves the span of the chosen directions by more than about 1 degree: detected
// generators carry noise (zdm2: (2, 0.002, -0.001) and (6, -0.001, 0.001) are one direction).
bool independent_of(const Vec3& t, const std::vector<GridDirection>& chosen) {
  if (chosen.empty()) return true;
  Eigen::Matrix<double, 3, Eigen::Dynamic> basis(3, static_cast<Eigen::Index>(chosen.size()));
  for (std::size_t i = 0; i < chosen.size(); ++i) basis.col(static_cast<Eigen::Index>(i)) = chosen[i].direction;
  const Vec3 unit = t.normalized();
  const Eigen::VectorXd coefficients = basis.colPivHouseholderQr().solve(unit);
  return (basis * coefficients - unit).norm() > kIndependentDirection;
}

// A family's members, generator first, then by power: a generator can be a motion that maps only
// outlines onto outlines (half a window pitch on a painted wall), while its square repeats whole
// units. Larger powers of a working generator would give fewer units.
std::vector<std::size_t> members_by_power(const SymmetryFamily& family) {
  std::vector<std::size_t> by_power(family.members.size());
  std::iota(by_power.begin(), by_power.end(), std::size_t{0});
  std::stable_sort(by_power.begin(), by_power.end(), [&](std::size_t a, std::size_t b) {
    return std::abs(family.powers[a]) < std::abs(family.powers[b]);
  });
  return by_power;
}

// The direction of a translation or screw family: its generator's, or when that gives none the
// next power's that does. A translation's direction whose units span a short run of the family's
// repeats gives way to the first larger power's that does not (the spans of a bridge, each with
// its pier and posts, rather than the posts between two piers).
std::optional<GridDirection> family_direction(const PreparedModel& prepared, const SymmetryResult& symmetries,
                                              const SymmetryFamily& family, const DirectionSearch& search) {
  auto direction_of = [&](std::size_t m) {
    return grid_direction(prepared, symmetries.symmetries[family.members[m]], family.members[m], search);
  };
  auto spans_short_run = [&](const GridDirection& direction, std::size_t m) {
    return family.kind == "translation" && short_run(direction.count * std::abs(family.powers[m]), family.count);
  };
  const std::vector<std::size_t> members = members_by_power(family);
  auto member = members.begin();
  std::optional<GridDirection> found;
  while (!found && member != members.end()) found = direction_of(*member++);
  if (!found || !spans_short_run(*found, *std::prev(member))) return found;
  for (; member != members.end(); ++member)
    if (std::optional<GridDirection> longer = direction_of(*member); longer && !spans_short_run(*longer, *member)) return longer;
  return found;
}

// Extent of a set of triangles along a direction and in space.
struct Extent {
  BoundingBox box;
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  double weighted_centre = 0.0, area = 0.0;  // area-weighted position of the triangle centres
};

// Places the groups of parts kept whole along `direction` (found on the rest of the model): a
// group whose centre lies before the middle of the units goes with the head, else with the tail.
// Fails when no unit holds a part (not kept whole) that lies inside it, or a group reaches across
// all units. Returns the fewest units at which the groups moved with the tail stay more than r from
// those placed with the head and out of the head's slab, and the head's groups out of the tail's.
std::optional<int> place_whole_parts(GridDirection& direction, const TriangleMesh& mesh, const ModelParts& model,
                                     const WholeParts& whole, double r) {
  const Vec3& d = direction.direction;
  const double first = direction.cut, last = direction.cut + direction.count * direction.pitch;
  std::map<std::uint32_t, Extent> groups;
  std::vector<Extent> parts(whole.kept.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::uint32_t p = model.part[t];
    Extent& e = whole.kept[p] ? groups[whole.group[p]] : parts[p];
    const auto corners = mesh.corners(t);
    for (const Vec3& x : corners) {
      e.box.add(x);
      e.lo = std::min(e.lo, d.dot(x));
      e.hi = std::max(e.hi, d.dot(x));
    }
    const double area = 0.5 * mesh.area_vector(t).norm();
    e.weighted_centre += area * d.dot((corners[0] + corners[1] + corners[2]) / 3.0);
    e.area += area;
  }
  const double margin = 1e-6 * direction.pitch;
  const bool unit_holds_a_part = std::any_of(parts.begin(), parts.end(), [&](const Extent& e) {
    if (e.area <= 0.0 || e.lo <= first + margin || e.hi >= last - margin) return false;
    return std::floor((e.lo - first) / direction.pitch) == std::floor((e.hi - first) / direction.pitch);
  });
  if (!unit_holds_a_part) return std::nullopt;
  const double middle = 0.5 * (first + last);
  std::vector<const Extent*> head, tail;
  std::map<std::uint32_t, bool> in_head;
  for (const auto& [group, e] : groups) {
    in_head[group] = e.weighted_centre < middle * e.area;
    (in_head[group] ? head : tail).push_back(&e);
  }
  int fewest = 0;
  for (const Extent* e : head) {
    if (e->hi + r > last) return std::nullopt;
    fewest = std::max(fewest, static_cast<int>(std::ceil((e->hi + r - first) / direction.pitch)));
  }
  for (const Extent* e : tail) {
    if (e->lo - r < first) return std::nullopt;
    fewest = std::max(fewest, direction.count - static_cast<int>(std::floor((e->lo - r - first) / direction.pitch)));
  }
  // Between those bounds a tail group moved back may still come near a head group.
  for (int units = direction.count - 1; units >= fewest; --units) {
    const Vec3 back = -(direction.count - units) * direction.translation;
    const bool meets = std::any_of(tail.begin(), tail.end(), [&](const Extent* t) {
      return std::any_of(head.begin(), head.end(), [&](const Extent* h) { return boxes_within(t->box.shifted(back), h->box, 2.0 * r); });
    });
    if (meets) {
      fewest = units + 1;
      break;
    }
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::uint32_t p = model.part[t];
    if (whole.kept[p]) (in_head[whole.group[p]] ? direction.whole_in_head : direction.whole_in_tail).push_back(static_cast<std::uint32_t>(t));
  }
  return fewest;
}

// Runs of a direction sought beyond its first, apart from each other.
constexpr std::size_t kFurtherRuns = 3;

// Members of a family tried for a row of parts: the generator and its square (each builds the
// voxel surface of the rest of the model and tests its every cell).
constexpr std::size_t kRowMembersTried = 2;

// A direction whose planes cut the model but for parts kept whole, and the fewest units it allows.
struct RowOfParts {
  GridDirection direction;
  int fewest_units = 0;
};

// The translation with the most units whose planes cut the model but for parts kept whole (for
// each family, the first member by power that gives one).
std::optional<RowOfParts> row_of_parts(const PreparedModel& prepared, const SymmetryResult& symmetries,
                                       const GridOptions& options) {
  const ModelParts parts = model_parts(prepared.model.mesh);
  // Families are independent: tried in parallel, compared in family order.
  std::vector<std::optional<RowOfParts>> rows(symmetries.families.size());
  tbb::parallel_for(std::size_t(0), rows.size(), [&](std::size_t f) {
    const SymmetryFamily& family = symmetries.families[f];
    if (family.kind != "translation" || family.count == 0) return;  // count 0: it only slides walls and rails
    const std::vector<std::size_t> by_power = members_by_power(family);
    for (std::size_t i = 0; i < std::min(by_power.size(), kRowMembersTried); ++i) {
      const std::size_t member = family.members[by_power[i]];
      const DetectedSymmetry& symmetry = symmetries.symmetries[member];
      if (!spans_pitches(prepared.cleaning.bounds, symmetry.transform.translation, options.min_repeats)) continue;
      const WholeParts whole = whole_parts(prepared, parts, symmetry, symmetries.region);
      if (whole.empty()) continue;
      // Parts are placed for the units between planes: no units beyond them.
      std::optional<GridDirection> direction = grid_direction(
          whole.rest, whole.motion, member, {.min_repeats = options.min_repeats, .max_slab_asymmetry = options.max_slab_asymmetry});
      if (!direction) continue;
      const std::optional<int> fewest = place_whole_parts(*direction, prepared.model.mesh, parts, whole, prepared.surface.r());
      if (!fewest) continue;
      rows[f] = RowOfParts{std::move(*direction), *fewest};
      return;
    }
  });
  std::optional<RowOfParts> best;
  for (std::optional<RowOfParts>& row : rows)
    if (row && (!best || row->direction.count > best->direction.count)) best = std::move(row);
  return best;
}

// Larger powers of a direction's generator tried for a grid of grouped units.
constexpr std::size_t kGroupingPowersTried = 4;

// Whether `grouped`, a direction of the `factor`-th power of `direction`'s generator, has two
// units or more that repeat over at least twice as many of the generator's pitches as
// `direction`'s units do.
bool groups_kept_units(const GridDirection& direction, const GridDirection& grouped, int factor) {
  const int repeated = direction.count - min_units(direction);
  const int grouped_repeated = factor * (grouped.count - min_units(grouped));
  return grouped.count >= 2 && grouped_repeated >= 2 * repeated;
}

// A direction of grid1 whose units differ every few units (a pilaster after every third window
// column keeps all but the columns between two pilasters once) grouped into units of a larger
// power of its generator that are all copies (bays of three columns and a pilaster): of the
// first kGroupingPowersTried larger powers of the family that do so, the one whose units repeat
// over the most of the generator's pitches (the smaller power on a tie).
std::optional<GridDirection> grouped_direction(const PreparedModel& prepared, const SymmetryResult& symmetries,
                                               const GridDirection& direction, const DirectionSearch& search) {
  const bool keeps_most_once = 2 * (direction.count - min_units(direction)) < direction.count;
  if (!direction.whole_in_head.empty() || !direction.whole_in_tail.empty() || !keeps_most_once) return std::nullopt;
  const DetectedSymmetry& generator = symmetries.symmetries[direction.symmetry];
  const SymmetryFamily& family = symmetries.families[generator.family];
  if (family.kind != "translation") return std::nullopt;
  const int power = std::abs(generator.power);
  std::optional<GridDirection> best;
  int best_pitches = 0;  // generator pitches the best one's repeated units span
  std::size_t tried = 0;
  for (std::size_t m : members_by_power(family)) {
    const int larger = std::abs(family.powers[m]);
    if (larger <= power || larger % power != 0) continue;
    if (tried++ == kGroupingPowersTried) break;
    const std::size_t member = family.members[m];
    std::optional<GridDirection> grouped = grid_direction(prepared, symmetries.symmetries[member], member, search);
    if (!grouped || !groups_kept_units(direction, *grouped, larger / power)) continue;
    const int pitches = larger / power * (grouped->count - min_units(*grouped));
    if (!best || pitches > best_pitches) best = std::move(grouped), best_pitches = pitches;
  }
  return best;
}

}  // namespace

std::optional<GroupedUnits> grouped_units(const GridRule& grid, const GridRule& other) {
  if (grid.directions.size() != other.directions.size()) return std::nullopt;
  std::optional<GroupedUnits> grouped;
  for (std::size_t i = 0; i < grid.directions.size(); ++i) {
    const GridDirection &own = grid.directions[i], &theirs = other.directions[i];
    const double close = 1e-6 * theirs.pitch;
    if (own.motion.angle() > 1e-9 || theirs.motion.angle() > 1e-9) return std::nullopt;  // screws
    if ((own.translation - theirs.translation).norm() <= close) continue;
    const long factor = std::lround(own.pitch / theirs.pitch);
    if (grouped || factor < 2 || (own.translation - static_cast<double>(factor) * theirs.translation).norm() > close)
      return std::nullopt;
    grouped = GroupedUnits{i, static_cast<int>(factor)};
  }
  return grouped;
}

std::vector<GridRule> find_grids(const PreparedModel& prepared, const SymmetryResult& symmetries,
                                 const GridOptions& options, const ProgressCallback& progress) {
  std::vector<GridRule> grids;
  std::vector<GridDirection> translations, screws;
  // Units near the model's ends that no plane may reach (r-erosion) count when they are copies
  // within the cells' offset tolerance the symmetries were found with (a point cloud's sampling
  // cannot tell a copy from a slab shifted by less than eps).
  const DirectionSearch search{
      .min_repeats = options.min_repeats,
      .max_slab_asymmetry = options.max_slab_asymmetry,
      .copy_tolerance =
          prepared.model.is_point_cloud() ? 0.0 : symmetries.region.offset_tolerance_eps * prepared.surface.eps()};
  std::vector<std::size_t> repeated_generators;  // translations that repeat but gave no direction
  // Families are independent: examined in parallel and joined in family order.
  const std::size_t family_count = symmetries.families.size();
  std::vector<std::optional<GridDirection>> found(family_count);
  parallel_for_reporting(family_count, progress, "grid rules", [&](std::size_t f) {
    const SymmetryFamily& family = symmetries.families[f];
    if (family.kind == "translation" || family.kind == "screw") found[f] = family_direction(prepared, symmetries, family, search);
  });
  for (std::size_t f = 0; f < family_count; ++f) {
    const SymmetryFamily& family = symmetries.families[f];
    if (found[f])
      (family.kind == "translation" ? translations : screws).push_back(*found[f]);
    else if (family.kind == "translation" && static_cast<int>(family.count) >= options.min_repeats)
      repeated_generators.push_back(family.members[members_by_power(family).front()]);
  }
  // Most units first; then combine independent translations into one grid.
  // Ties keep a readable order: directions closest to x, then y, then z.
  auto axis_of = [](const GridDirection& d) {
    Eigen::Index axis = 0;
    d.direction.cwiseAbs().maxCoeff(&axis);
    return axis;
  };
  auto more_units = [&](const GridDirection& a, const GridDirection& b) {
    return a.count != b.count ? a.count > b.count : axis_of(a) < axis_of(b);
  };
  // A translation along a screw's axis by a whole number (two or more) of its slides gives way to
  // the screw when that has more units: its units hold several of the screw's. It is a power of
  // the screw (a full turn of a spiral stair that climbs more than one), or one composed with a
  // turn that each unit survives (a chain whose links turn by a quarter turn each: two links on
  // is a half turn of the screw and each link's own half turn). A translation that forms a grid
  // with another of min_repeats units across it stays: the screw could join no such grid (a
  // staggered brick wall's half turn about its length with a slide of half a brick has twice the
  // units of the brick pitch, which with the pitch of two courses makes the wall's 2-grid).
  const std::vector<GridDirection> found_translations = translations;
  auto forms_a_grid = [&](const GridDirection& translation) {
    return std::any_of(found_translations.begin(), found_translations.end(), [&](const GridDirection& other) {
      return other.count >= options.min_repeats && independent_of(other.translation, {translation});
    });
  };
  std::erase_if(translations, [&](const GridDirection& translation) {
    return !forms_a_grid(translation) && std::any_of(screws.begin(), screws.end(), [&](const GridDirection& screw) {
      const int turn = static_cast<int>(std::lround(translation.pitch / screw.pitch));
      return screw.count > translation.count && turn >= 2 && !independent_of(translation.translation, {screw}) &&
             std::abs(translation.pitch - turn * screw.pitch) <= prepared.surface.eps();
    });
  });
  std::stable_sort(translations.begin(), translations.end(), more_units);
  std::stable_sort(screws.begin(), screws.end(), more_units);
  auto next_grid = [&]() {
    GridRule grid;
    grid.name = "grid" + std::to_string(grids.size() + 1);
    grid.max_count = options.max_count;
    return grid;
  };
  GridRule grid = next_grid();
  for (const GridDirection& direction : translations)
    if (grid.directions.size() < 3 && independent_of(direction.translation, grid.directions)) grid.directions.push_back(direction);
  // A translation the model repeats (as many of its powers are symmetries) whose planes fit only
  // one unit across the whole model, because of parts such as rooftop structures between the bays
  // of a facade, joins a grid that exists as a direction with one unit: resizing adds bays where
  // the planes are free.
  for (std::size_t s : repeated_generators) {
    if (grid.directions.empty() || grid.directions.size() >= 3 ||
        !independent_of(symmetries.symmetries[s].transform.translation, grid.directions))
      continue;
    DirectionSearch single = search;
    single.min_repeats = 1;
    if (auto direction = grid_direction(prepared, symmetries.symmetries[s], s, single))
      grid.directions.push_back(*direction);
  }
  // No translation cuts across the whole model: a row of parts may, keeping other parts whole
  // (a mesh's connected components; a point cloud has none).
  if (grid.directions.empty() && !prepared.model.is_point_cloud())
    if (std::optional<RowOfParts> row = row_of_parts(prepared, symmetries, options)) {
      grid.min_count = row->fewest_units;
      grid.directions.push_back(std::move(row->direction));
    }
  if (!grid.directions.empty()) grids.push_back(std::move(grid));
  // A screw commutes only with motions along its own axis, so each screw is a 1-grid of its own;
  // screws along the same axis (powers of one another, one screw found twice, or an axis the
  // translation grid already cuts across) give no further grid.
  std::vector<GridDirection> chosen_screws = grids.empty() ? std::vector<GridDirection>{} : grids[0].directions;
  for (const GridDirection& direction : screws) {
    if (!independent_of(direction.translation, chosen_screws)) continue;
    chosen_screws.push_back(direction);
    GridRule screw_grid = next_grid();
    screw_grid.directions.push_back(direction);
    grids.push_back(std::move(screw_grid));
  }
  // Further runs of grid1's directions, apart from the first (fences on both sides of a gate):
  // each is a 1-grid of its own, its planes clear of the runs found before.
  if (!grids.empty() && !prepared.model.is_point_cloud()) {
    const std::vector<GridDirection> first_runs = grids[0].directions;
    for (const GridDirection& run : first_runs) {
      if (run.count < options.min_repeats || !run.whole_in_head.empty() || !run.whole_in_tail.empty()) continue;
      DirectionSearch further_search = search;
      further_search.taken = {{run.cut, run.cut + run.count * run.pitch}};
      while (further_search.taken.size() <= kFurtherRuns) {
        std::optional<GridDirection> further =
            grid_direction(prepared, symmetries.symmetries[run.symmetry], run.symmetry, further_search);
        if (!further) break;
        further_search.taken.emplace_back(further->cut, further->cut + further->count * further->pitch);
        GridRule further_grid = next_grid();
        further_grid.directions.push_back(std::move(*further));
        grids.push_back(std::move(further_grid));
      }
    }
  }
  // Grid1's directions whose units differ every few units give grids of their own with grouped
  // units in that direction, the other directions as in grid1 (resizing adds whole bays).
  if (!grids.empty() && !prepared.model.is_point_cloud()) {
    const GridRule first = grids[0];
    for (std::size_t i = 0; i < first.directions.size(); ++i)
      if (auto grouped = grouped_direction(prepared, symmetries, first.directions[i], search)) {
        GridRule grouped_grid = next_grid();
        grouped_grid.directions = first.directions;
        grouped_grid.directions[i] = std::move(*grouped);
        grids.push_back(std::move(grouped_grid));
      }
  }
  report_progress(progress, "grid rules", 1.0);
  return grids;
}

}  // namespace dg
