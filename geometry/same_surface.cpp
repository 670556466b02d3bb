#include "geometry/same_surface.h"

#include "geometry/cell_key.h"
#include "geometry/flat_regions.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

namespace dg {
namespace {

// Edge of the blocks of cells that limit sampling to where it can matter (in cells).
constexpr std::int64_t kBlockCells = 16;

CellKey block_of(const CellKey& k) {
  auto floor_div = [](std::int64_t v) { return v >= 0 ? v / kBlockCells : -((-v + kBlockCells - 1) / kBlockCells); };
  return {floor_div(k[0]), floor_div(k[1]), floor_div(k[2])};
}

// The blocks that hold `cells` and their 26 neighbours: every cell within kBlockCells cells of
// one of `cells` lies in one of them. Sorted, without repeats.
std::vector<CellKey> blocks_around(const std::vector<CellKey>& cells) {
  std::vector<CellKey> held;
  for (const CellKey& k : cells) held.push_back(block_of(k));
  std::sort(held.begin(), held.end());
  held.erase(std::unique(held.begin(), held.end()), held.end());
  std::vector<CellKey> blocks;
  for (const CellKey& b : held)
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) blocks.push_back({b[0] + dx, b[1] + dy, b[2] + dz});
  std::sort(blocks.begin(), blocks.end());
  blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());
  return blocks;
}

// The cells (cubes of edge `cell`, model units) that points of the listed triangles of `mesh`
// fall in, sampled on each triangle in rows parallel to its longest edge, at most one cell apart
// along and across them (so a sliver costs as few samples as its area needs; a cell the surface
// only clips may be missed, but a neighbour of it is not); sorted, without repeats. With
// `blocks` (sorted, see blocks_around), only the cells inside those blocks: a row skips the
// samples of each other block it crosses (the same samples are taken inside them).
std::vector<CellKey> surface_cells(const TriangleMesh& mesh, const std::vector<std::size_t>& triangles, double cell,
                                   const std::vector<CellKey>* blocks = nullptr) {
  std::vector<CellKey> cells;
  auto compact = [&] {
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  };
  std::size_t compact_at = 4096;
  for (std::size_t t : triangles) {
    auto [a, b, c] = mesh.corners(t);
    // Make a-b the longest edge.
    if ((c - b).norm() > (b - a).norm() && (c - b).norm() >= (a - c).norm()) std::tie(a, b, c) = std::tuple{b, c, a};
    else if ((a - c).norm() > (b - a).norm()) std::tie(a, b, c) = std::tuple{c, a, b};
    const double length = (b - a).norm();
    const double height = length > 0.0 ? (b - a).cross(c - a).norm() / length : (c - a).norm();
    const int rows = std::max(1, static_cast<int>(std::ceil(height / cell)));
    for (int k = 0; k <= rows; ++k) {
      const double s = static_cast<double>(k) / rows;  // row from a-b (s = 0) to c (s = 1)
      const Vec3 from = a + s * (c - a), to = b + s * (c - b);
      const int steps = std::max(1, static_cast<int>(std::ceil((1.0 - s) * length / cell)));
      const Vec3 along = to - from;
      for (int i = 0; i <= steps;) {
        const Vec3 p = from + (static_cast<double>(i) / steps) * along;
        const CellKey key = cell_key(p, cell);
        if (!blocks) {
          cells.push_back(key);
          ++i;
          continue;
        }
        const CellKey block = block_of(key);
        if (std::binary_search(blocks->begin(), blocks->end(), block)) {
          cells.push_back(key);
          ++i;
          continue;
        }
        // Where the row leaves this block (a box, so the samples before lie inside it).
        double leaves = std::numeric_limits<double>::infinity();
        for (int axis = 0; axis < 3; ++axis) {
          const double lo = static_cast<double>(block[static_cast<std::size_t>(axis)] * kBlockCells) * cell;
          const double hi = lo + static_cast<double>(kBlockCells) * cell;
          if (along[axis] > 0.0) leaves = std::min(leaves, (hi - from[axis]) / along[axis]);
          if (along[axis] < 0.0) leaves = std::min(leaves, (lo - from[axis]) / along[axis]);
        }
        const double next = std::floor(leaves * steps);
        i = next > static_cast<double>(steps) ? steps + 1 : std::max(i + 1, static_cast<int>(next));
      }
    }
    // Many samples fall in one cell: repeats go whenever the list doubles, so memory follows the
    // cells, not the samples.
    if (cells.size() >= compact_at) {
      compact();
      compact_at = 2 * cells.size() + 4096;
    }
  }
  compact();
  return cells;
}

// Every cell of `a` is a cell of `b` or lies within `rings` cells of one; both sorted. Cells in
// both are found by walking the two lists together; only the others search their neighbours.
bool cells_covered(const std::vector<CellKey>& a, const std::vector<CellKey>& b, std::int64_t rings = 1) {
  auto in_b = b.begin();
  for (const CellKey& k : a) {
    while (in_b != b.end() && *in_b < k) ++in_b;
    if (in_b != b.end() && *in_b == k) continue;
    bool near = false;
    for (std::int64_t dx = -rings; dx <= rings && !near; ++dx)
      for (std::int64_t dy = -rings; dy <= rings && !near; ++dy)
        for (std::int64_t dz = -rings; dz <= rings && !near; ++dz)
          near = std::binary_search(b.begin(), b.end(), CellKey{k[0] + dx, k[1] + dy, k[2] + dz});
    if (!near) return false;
  }
  return true;
}

// The triangles of `mesh` per material index (one entry for a mesh without materials), with
// their area (model units^2).
struct MaterialPart {
  std::vector<std::size_t> triangles;
  double area = 0.0;
};
std::map<std::uint32_t, MaterialPart> parts_by_material(const TriangleMesh& mesh) {
  std::map<std::uint32_t, MaterialPart> parts;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    MaterialPart& part = parts[mesh.has_materials() ? mesh.materials[t] : 0];
    part.triangles.push_back(t);
    part.area += 0.5 * mesh.area_vector(t).norm();
  }
  return parts;
}

// Pairs triangles of `a` and `b` not yet flagged (in `twin_a`, `twin_b`) that have the same
// material and whose corners lie within `distance` (model units) of each other's, in any order:
// corners on either side of a cell boundary. Each such triangle of `a`, in order, takes the first
// unflagged one of `b` found; both are flagged.
void pair_close_triangles(const TriangleMesh& a, const TriangleMesh& b, double distance, std::vector<char>& twin_a,
                          std::vector<char>& twin_b) {
  auto centroid = [](const TriangleMesh& mesh, std::size_t t) {
    const auto [p, q, r] = mesh.corners(t);
    return Vec3((p + q + r) / 3.0);
  };
  std::unordered_map<CellKey, std::vector<std::size_t>, CellKeyHash> b_by_centroid;
  for (std::size_t t = 0; t < b.triangles.size(); ++t)
    if (!twin_b[t]) b_by_centroid[cell_key(centroid(b, t), distance)].push_back(t);
  if (b_by_centroid.empty()) return;
  auto material = [](const TriangleMesh& mesh, std::size_t t) { return mesh.has_materials() ? mesh.materials[t] : 0u; };
  auto corners_near = [&](const std::array<Vec3, 3>& x, const std::array<Vec3, 3>& y) {
    return std::all_of(x.begin(), x.end(), [&](const Vec3& p) {
      return std::any_of(y.begin(), y.end(), [&](const Vec3& q) { return (p - q).norm() <= distance; });
    });
  };
  for (std::size_t t = 0; t < a.triangles.size(); ++t) {
    if (twin_a[t]) continue;
    const std::array<Vec3, 3> corners = a.corners(t);
    const CellKey k = cell_key(centroid(a, t), distance);
    for (std::int64_t dx = -1; dx <= 1 && !twin_a[t]; ++dx)
      for (std::int64_t dy = -1; dy <= 1 && !twin_a[t]; ++dy)
        for (std::int64_t dz = -1; dz <= 1 && !twin_a[t]; ++dz) {
          const auto found = b_by_centroid.find({k[0] + dx, k[1] + dy, k[2] + dz});
          if (found == b_by_centroid.end()) continue;
          for (std::size_t u : found->second) {
            if (twin_b[u] || material(a, t) != material(b, u)) continue;
            const std::array<Vec3, 3> other = b.corners(u);
            if (corners_near(corners, other) && corners_near(other, corners)) {
              twin_a[t] = twin_b[u] = 1;
              break;
            }
          }
        }
  }
}

// Flags per triangle of `a` and of `b`: 1 when it has a twin in the other mesh, a triangle of the
// same material whose corners fall in the same cells of edge `cell` (model units; the grid is
// offset so round coordinates lie inside cells), in any order, or lie within `cell` of its
// corners where they fall in different cells. Twins are paired one to one.
std::pair<std::vector<char>, std::vector<char>> twin_triangles(const TriangleMesh& a, const TriangleMesh& b, double cell) {
  const Vec3 offset = cell * Vec3(0.381966, 0.267949, 0.414214);
  using Key = std::array<std::int64_t, 10>;  // material, then the sorted corner cells
  auto keys = [&](const TriangleMesh& mesh) {
    std::vector<std::pair<Key, std::size_t>> out;
    out.reserve(mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const auto [p, q, r] = mesh.corners(t);
      std::array<CellKey, 3> corners{cell_key(p + offset, cell), cell_key(q + offset, cell), cell_key(r + offset, cell)};
      std::sort(corners.begin(), corners.end());
      Key key{mesh.has_materials() ? static_cast<std::int64_t>(mesh.materials[t]) : 0};
      for (std::size_t c = 0; c < 3; ++c)
        std::copy(corners[c].begin(), corners[c].end(), key.begin() + 1 + 3 * static_cast<std::ptrdiff_t>(c));
      out.emplace_back(key, t);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  const auto keys_a = keys(a), keys_b = keys(b);
  std::vector<char> twin_a(a.triangles.size(), 0), twin_b(b.triangles.size(), 0);
  for (auto i = keys_a.begin(), j = keys_b.begin(); i != keys_a.end() && j != keys_b.end();) {
    if (i->first < j->first) {
      ++i;
    } else if (j->first < i->first) {
      ++j;
    } else {
      twin_a[(i++)->second] = 1;
      twin_b[(j++)->second] = 1;
    }
  }
  pair_close_triangles(a, b, cell, twin_a, twin_b);
  return {std::move(twin_a), std::move(twin_b)};
}

// Flags the triangles of the flat regions of `a` that hold a triangle not yet flagged in
// `done_a` and are one region with such a region of `b` (same_flat_region within tolerance / 2,
// so that a production merged with a look-alike still rebuilds its exemplar within tolerance);
// and the other way round. Cutting pieces apart and merging their flat faces again triangulates
// one region in different ways.
void flag_same_flat_regions(const TriangleMesh& a, const TriangleMesh& b, std::vector<char>& done_a, std::vector<char>& done_b,
                            double tolerance) {
  auto not_done = [](const std::vector<char>& done) {
    std::vector<char> wanted(done.size());
    std::transform(done.begin(), done.end(), wanted.begin(), [](char d) { return static_cast<char>(d == 0); });
    return wanted;
  };
  const std::vector<FlatRegion> regions_a = flat_regions(a, not_done(done_a));
  if (regions_a.empty()) return;
  const std::vector<FlatRegion> regions_b = flat_regions(b, not_done(done_b));
  std::vector<char> matched_a(regions_a.size(), 0), matched_b(regions_b.size(), 0);
  for (std::size_t i = 0; i < regions_a.size(); ++i)
    for (std::size_t j = 0; j < regions_b.size(); ++j)
      if (same_flat_region(regions_a[i], regions_b[j], 0.5 * tolerance)) matched_a[i] = matched_b[j] = 1;
  for (std::size_t i = 0; i < regions_a.size(); ++i)
    if (matched_a[i])
      for (std::uint32_t t : regions_a[i].triangles) done_a[t] = 1;
  for (std::size_t j = 0; j < regions_b.size(); ++j)
    if (matched_b[j])
      for (std::uint32_t t : regions_b[j].triangles) done_b[t] = 1;
}

// Pairs of triangles up to which `near_triangles` tests each triangle of `to` against each of
// `from` before it keeps those near any; beyond, those near all of `from` are kept.
constexpr std::size_t kNearPairsTested = 1u << 22;

// The listed triangles of `to` whose bounding boxes come within `reach` (model units) of those
// of the listed triangles of `from` (of all of them together when the pairs are too many).
std::vector<std::size_t> near_triangles(const TriangleMesh& from, const std::vector<std::size_t>& from_triangles,
                                        const TriangleMesh& to, const std::vector<std::size_t>& to_triangles, double reach) {
  if (from_triangles.empty()) return {};
  auto box = [](const TriangleMesh& mesh, std::size_t t) {
    BoundingBox b;
    for (const Vec3& p : mesh.corners(t)) b.add(p);
    return b;
  };
  auto meet = [&](const BoundingBox& x, const BoundingBox& y) { return boxes_within(x, y, reach); };
  std::vector<BoundingBox> from_boxes;
  BoundingBox all;
  for (std::size_t t : from_triangles) {
    from_boxes.push_back(box(from, t));
    all.add(from_boxes.back().min);
    all.add(from_boxes.back().max);
  }
  std::vector<std::size_t> near;
  for (std::size_t t : to_triangles)
    if (meet(all, box(to, t))) near.push_back(t);
  if (near.size() * from_boxes.size() <= kNearPairsTested)
    std::erase_if(near, [&](std::size_t t) {
      const BoundingBox b = box(to, t);
      return std::none_of(from_boxes.begin(), from_boxes.end(), [&](const BoundingBox& f) { return meet(f, b); });
    });
  return near;
}

// Cells of a surface up to which a comparison samples it on the cells it asks for; a larger
// surface is sampled on cells grown to stay within this many (its test then allows more).
constexpr double kMostSurfaceCells = 1 << 20;

// One side of a comparison: triangles of `from` (of total `area`, model units^2) that must be
// covered by the listed ones of `to`.
struct CoverTest {
  const TriangleMesh* from;
  std::vector<std::size_t> from_triangles;
  double area = 0.0;
  const TriangleMesh* to;
  std::vector<std::size_t> to_triangles;

  // Whether every cell of edge `cell` (grown for large surfaces, kMostSurfaceCells) the `from`
  // triangles pass through lies within `rings` (< kBlockCells) cells of one the `to` triangles
  // pass through; the `to` triangles are sampled only in the blocks around the `from` cells.
  bool holds(double cell, std::int64_t rings) const {
    const double sampled = std::max(cell, std::sqrt(area / kMostSurfaceCells));
    const std::vector<CellKey> from_cells = surface_cells(*from, from_triangles, sampled);
    const std::vector<CellKey> blocks = blocks_around(from_cells);
    return cells_covered(from_cells, surface_cells(*to, to_triangles, sampled, &blocks), rings);
  }
};

}  // namespace

bool same_surface(const TriangleMesh& a, const TriangleMesh& b, double tolerance) {
  const BoundingBox ba = a.bounds(), bb = b.bounds();
  if ((ba.min - bb.min).norm() > tolerance || (ba.max - bb.max).norm() > tolerance) return false;
  // Each material's surface covers the other's; a material with no more than tolerance^2 of area
  // in one mesh may be missing from the other.
  const std::map<std::uint32_t, MaterialPart> parts_a = parts_by_material(a), parts_b = parts_by_material(b);
  const double negligible = tolerance * tolerance;
  auto matched = [&](const std::map<std::uint32_t, MaterialPart>& from, const std::map<std::uint32_t, MaterialPart>& to) {
    return std::all_of(from.begin(), from.end(), [&](const auto& entry) {
      return entry.second.area <= negligible || to.contains(entry.first);
    });
  };
  if (!matched(parts_a, parts_b) || !matched(parts_b, parts_a)) return false;
  // Twins (corners within tolerance / 8, or in one cell of that edge) cover each other: only the
  // other triangles are sampled, against the other mesh's triangles near them (cells of one
  // surface touch the other's only through triangles whose boxes come within 2 tolerance of
  // theirs). Exact copies cut alike have no others.
  auto [twin_a, twin_b] = twin_triangles(a, b, tolerance / 8.0);
  auto cover_tests = [&] {
    auto without_twins = [](std::vector<std::size_t> triangles, const std::vector<char>& twin) {
      std::erase_if(triangles, [&](std::size_t t) { return twin[t] != 0; });
      return triangles;
    };
    std::vector<CoverTest> tests;
    for (const auto& [material, part_a] : parts_a) {
      const auto found = parts_b.find(material);
      if (found == parts_b.end()) continue;
      const std::vector<std::size_t>& triangles_b = found->second.triangles;
      for (auto [from, from_all, twin, to, to_all] : {std::tuple{&a, &part_a.triangles, &twin_a, &b, &triangles_b},
                                                       std::tuple{&b, &triangles_b, &twin_b, &a, &part_a.triangles}}) {
        std::vector<std::size_t> rest = without_twins(*from_all, *twin);
        if (rest.empty()) continue;
        double area = 0.0;
        for (std::size_t t : rest) area += 0.5 * from->area_vector(t).norm();
        std::vector<std::size_t> near = near_triangles(*from, rest, *to, *to_all, 2.0 * tolerance);
        tests.push_back(CoverTest{from, std::move(rest), area, to, std::move(near)});
      }
    }
    return tests;
  };
  // The sides are independent: tested in parallel, each pass stopping once one side fails.
  auto all_hold = [](const std::vector<CoverTest>& tests, double cell, std::int64_t rings) {
    std::atomic<bool> failed{false};
    tbb::parallel_for(std::size_t(0), tests.size(), [&](std::size_t i) {
      if (!failed.load(std::memory_order_relaxed) && !tests[i].holds(cell, rings)) failed.store(true, std::memory_order_relaxed);
    });
    return !failed.load();
  };
  // Surfaces that pass on cells of tolerance / 2 lie within about 1.7 tolerance of each other,
  // so on cells of 8 tolerance within two of each other's (one for the distance, one for a cell
  // the sampling missed): most differing surfaces fail there first, at 1/256 of the samples.
  if (!all_hold(cover_tests(), 8.0 * tolerance, 2)) return false;
  // Flat regions with the same plane and outline cover each other too, however triangulated.
  // The tests are built again without them, so that the other mesh's triangles kept near the
  // rest shrink too (kept from the coarse pass, the fine pass would still sample the partners of
  // the regions set aside).
  flag_same_flat_regions(a, b, twin_a, twin_b, tolerance);
  return all_hold(cover_tests(), 0.5 * tolerance, 1);
}

bool same_points(const PointCloud& a, const PointCloud& b, double tolerance) {
  if (a.positions.empty() || b.positions.empty()) return a.positions.empty() == b.positions.empty();
  const BoundingBox ba = a.bounds(), bb = b.bounds();
  if ((ba.min - bb.min).norm() > 2.0 * tolerance || (ba.max - bb.max).norm() > 2.0 * tolerance) return false;
  auto cells_of = [&](const PointCloud& cloud) {
    std::vector<CellKey> cells;
    for (const Vec3& p : cloud.positions) cells.push_back(cell_key(p, tolerance));
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    return cells;
  };
  const std::vector<CellKey> cells_a = cells_of(a), cells_b = cells_of(b);
  return cells_covered(cells_a, cells_b) && cells_covered(cells_b, cells_a);
}

}  // namespace dg
