#include "geometry/zone_cut.h"

#include <algorithm>
#include <functional>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <unordered_map>

namespace dg {
namespace {

constexpr std::uint32_t kNoVertex = std::numeric_limits<std::uint32_t>::max();
using EdgeKey = std::uint64_t;

EdgeKey key_of(std::uint32_t a, std::uint32_t b) {
  const auto [lo, hi] = std::minmax(a, b);
  return (static_cast<EdgeKey>(lo) << 32) | hi;
}

struct Piece {
  Triangle corners;
  std::uint32_t origin;
};

class ZoneCutter {
 public:
  ZoneCutter(const TriangleMesh& mesh, double tolerance)
      : positions_(mesh.positions), original_count_(static_cast<std::uint32_t>(mesh.positions.size())), tolerance_(tolerance) {}

  // Cuts the pieces `wanted` accepts along every plane of `family`; the pieces are replaced by
  // their parts.
  void cut(std::vector<Piece>& pieces, const PlaneFamily& family, std::size_t family_index, const PieceFilter& wanted) {
    if (family.offsets.empty()) return;
    family_ = family_index;
    direction_ = family.direction;
    offsets_ = &family.offsets;
    wanted_ = &wanted;
    level_.assign(positions_.size(), std::numeric_limits<double>::quiet_NaN());
    crossings_.clear();
    for (const Piece& p : pieces)
      for (std::uint32_t v : p.corners) snap(v);
    std::vector<Piece> done, stack;
    for (const Piece& p : pieces) {
      stack.assign(1, p);
      while (!stack.empty()) {
        const Piece piece = stack.back();
        stack.pop_back();
        split(piece, done, stack);
      }
    }
    pieces = std::move(done);
  }

  // The vertices created on line `line` strictly between a and b, ordered from a to b.
  std::vector<std::uint32_t> inner_vertices(std::uint32_t a, std::uint32_t b) const {
    std::vector<std::uint32_t> inner;
    const auto found = on_line_.find(line(a, b));
    if (found == on_line_.end()) return inner;
    const Vec3 pa = positions_[a], ab = positions_[b] - pa;
    const double length2 = ab.squaredNorm();
    std::vector<std::pair<double, std::uint32_t>> ordered;
    for (std::uint32_t v : found->second) {
      if (v == a || v == b) continue;
      const double s = (positions_[v] - pa).dot(ab) / length2;
      if (s > 0.0 && s < 1.0) ordered.emplace_back(s, v);
    }
    std::sort(ordered.begin(), ordered.end());
    for (const auto& [s, v] : ordered) inner.push_back(v);
    return inner;
  }

  const std::vector<Vec3>& positions() const { return positions_; }

 private:
  static constexpr EdgeKey kNoEdge = std::numeric_limits<EdgeKey>::max();

  // Level of vertex v along the family direction; vertices near a plane are moved onto it.
  void snap(std::uint32_t v) {
    if (!std::isnan(level_[v])) return;
    double s = direction_.dot(positions_[v]);
    const auto& offsets = *offsets_;
    const auto above = std::lower_bound(offsets.begin(), offsets.end(), s);
    double nearest = std::numeric_limits<double>::infinity();
    if (above != offsets.end()) nearest = *above;
    if (above != offsets.begin() && std::abs(*(above - 1) - s) < std::abs(nearest - s)) nearest = *(above - 1);
    if (std::abs(nearest - s) <= tolerance_ && nearest != s) {
      positions_[v] += (nearest - s) * direction_;
      s = nearest;
    }
    level_[v] = s;
  }

  // The line (input edge or cut chord) that edge a-b of the current pieces lies on.
  EdgeKey line(std::uint32_t a, std::uint32_t b) const {
    if (a < original_count_ && b < original_count_) return key_of(a, b);  // cuts never join two input vertices
    const auto found = line_of_edge_.find(key_of(a, b));
    return found == line_of_edge_.end() ? kNoEdge : found->second;
  }

  // A new edge a-b along a new chord.
  void add_chord(std::uint32_t a, std::uint32_t b) { line_of_edge_[key_of(a, b)] = kChord | chords_++; }

  // The vertex where edge a-b crosses the plane at `offset` (shared by both triangles of the edge).
  std::uint32_t crossing(std::uint32_t a, std::uint32_t b, double offset) {
    const EdgeKey k = key_of(a, b);
    const auto found = crossings_.find(k);
    if (found != crossings_.end()) return found->second;
    const auto [lo, hi] = std::minmax(a, b);  // same arithmetic from both triangles
    const double t = (offset - level_[lo]) / (level_[hi] - level_[lo]);
    Vec3 p = positions_[lo] + t * (positions_[hi] - positions_[lo]);
    p += (offset - direction_.dot(p)) * direction_;
    const EdgeKey on = line(a, b);
    // A neighbour that was cut differently may have made this point already (on a longer edge
    // of the same line): use that vertex.
    if (const auto made = on_line_.find(on); made != on_line_.end())
      for (std::uint32_t v : made->second)
        if ((positions_[v] - p).norm() <= tolerance_) {
          line_of_edge_[key_of(a, v)] = on;
          line_of_edge_[key_of(v, b)] = on;
          if (std::isnan(level_[v])) level_[v] = offset;
          crossings_.emplace(k, v);
          return v;
        }
    const auto index = static_cast<std::uint32_t>(positions_.size());
    positions_.push_back(p);
    level_.push_back(offset);
    line_of_edge_[key_of(a, index)] = on;
    line_of_edge_[key_of(index, b)] = on;
    on_line_[on].push_back(index);
    crossings_.emplace(k, index);
    return index;
  }

  // Splits `piece` along the lowest plane strictly inside its range: parts below are done,
  // parts above may cross further planes.
  void split(const Piece& piece, std::vector<Piece>& done, std::vector<Piece>& stack) {
    const Triangle& t = piece.corners;
    const double lo = std::min({level_[t[0]], level_[t[1]], level_[t[2]]});
    const double hi = std::max({level_[t[0]], level_[t[1]], level_[t[2]]});
    auto plane = std::upper_bound(offsets_->begin(), offsets_->end(), lo);
    if (*wanted_) {
      const std::array<Vec3, 3> corners{positions_[t[0]], positions_[t[1]], positions_[t[2]]};
      while (plane != offsets_->end() && *plane < hi && !(*wanted_)(corners, family_, *plane)) ++plane;
    }
    if (plane == offsets_->end() || !(*plane < hi)) {
      done.push_back(piece);
      return;
    }
    const double offset = *plane;
    auto side = [&](std::uint32_t v) { return level_[v] - offset; };
    // Rotate so that the corner alone on its side comes first (the others are on the other
    // side or on the plane).
    int alone = 0;
    for (int k = 0; k < 3; ++k) {
      const double a = side(t[k]), b = side(t[(k + 1) % 3]), c = side(t[(k + 2) % 3]);
      if ((a > 0 && b <= 0 && c <= 0) || (a < 0 && b >= 0 && c >= 0)) {
        alone = k;
        break;
      }
    }
    const std::uint32_t a = t[alone], b = t[(alone + 1) % 3], c = t[(alone + 2) % 3];
    std::vector<Piece> parts;
    if (side(c) == 0.0) {  // plane through c
      const std::uint32_t ab = crossing(a, b, offset);
      add_chord(ab, c);
      parts = {{{a, ab, c}, piece.origin}, {{ab, b, c}, piece.origin}};
    } else if (side(b) == 0.0) {  // plane through b
      const std::uint32_t ca = crossing(c, a, offset);
      add_chord(ca, b);
      parts = {{{a, b, ca}, piece.origin}, {{ca, b, c}, piece.origin}};
    } else {
      const std::uint32_t ab = crossing(a, b, offset), ca = crossing(c, a, offset);
      add_chord(ab, ca);
      add_chord(ab, c);
      parts = {{{a, ab, ca}, piece.origin}, {{ab, b, c}, piece.origin}, {{ab, c, ca}, piece.origin}};
    }
    for (const Piece& part : parts) {
      const double top = std::max({level_[part.corners[0]], level_[part.corners[1]], level_[part.corners[2]]});
      (top > offset ? stack : done).push_back(part);
    }
  }

  static constexpr EdgeKey kChord = EdgeKey{1} << 63;

  std::vector<Vec3> positions_;
  std::uint32_t original_count_;
  std::unordered_map<EdgeKey, EdgeKey> line_of_edge_;              // edges with a new vertex -> their line
  std::unordered_map<EdgeKey, std::vector<std::uint32_t>> on_line_;  // line -> new vertices on it
  EdgeKey chords_ = 0;
  double tolerance_;
  const PieceFilter* wanted_ = nullptr;
  std::size_t family_ = 0;
  Vec3 direction_ = Vec3::UnitX();
  const std::vector<double>* offsets_ = nullptr;
  std::vector<double> level_;  // per vertex: direction . position, NaN until needed
  std::unordered_map<EdgeKey, std::uint32_t> crossings_;
};

// Adds triangle t to `out`, split at the vertices other pieces created on its edges.
void add_conforming(const Triangle& t, const ZoneCutter& cutter, std::vector<Vec3>& positions, std::uint32_t origin,
                    ZoneCut& out) {
  std::array<std::vector<std::uint32_t>, 3> inner;
  int split_edges = 0;
  for (int k = 0; k < 3; ++k) {
    inner[k] = cutter.inner_vertices(t[k], t[(k + 1) % 3]);
    split_edges += inner[k].empty() ? 0 : 1;
  }
  auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    out.mesh.triangles.push_back({a, b, c});
    out.origin.push_back(origin);
  };
  if (split_edges == 0) {
    add(t[0], t[1], t[2]);
    return;
  }
  if (split_edges == 1) {  // a fan from the corner opposite the split edge
    for (int k = 0; k < 3; ++k) {
      if (inner[k].empty()) continue;
      std::uint32_t previous = t[k];
      for (std::uint32_t v : inner[k]) add(previous, v, t[(k + 2) % 3]), previous = v;
      add(previous, t[(k + 1) % 3], t[(k + 2) % 3]);
    }
    return;
  }
  // Several split edges: a fan from the centroid around the boundary polygon.
  const auto centre = static_cast<std::uint32_t>(positions.size());
  positions.push_back((positions[t[0]] + positions[t[1]] + positions[t[2]]) / 3.0);
  std::vector<std::uint32_t> loop;
  for (int k = 0; k < 3; ++k) {
    loop.push_back(t[k]);
    loop.insert(loop.end(), inner[k].begin(), inner[k].end());
  }
  for (std::size_t i = 0; i < loop.size(); ++i) add(loop[i], loop[(i + 1) % loop.size()], centre);
}

// Cuts along different lines can make vertices at one spot (a plane through a point another
// chord already made): every new vertex within `tolerance` of an earlier vertex of the cut
// becomes that vertex, and triangles left with a repeated corner go. Vertices below
// `first_new` never merge with each other, so input indices stay meaningful.
void merge_coincident(ZoneCut& out, std::uint32_t first_new, const std::vector<char>& touched, double tolerance) {
  const double cell = 4.0 * std::max(tolerance, 1e-300);
  using Key = std::array<std::int64_t, 3>;
  auto key = [&](const Vec3& p) {
    return Key{static_cast<std::int64_t>(std::floor(p.x() / cell)), static_cast<std::int64_t>(std::floor(p.y() / cell)),
               static_cast<std::int64_t>(std::floor(p.z() / cell))};
  };
  std::map<Key, std::vector<std::uint32_t>> grid;
  const std::vector<Vec3>& positions = out.mesh.positions;
  // Touching parts cut along one plane (a leg's top under a seat) make vertices at one spot on
  // surfaces that face away from each other: those stay apart, as the parts were.
  const std::vector<Vec3> normals = vertex_normals(out.mesh);
  std::vector<std::uint32_t> target(positions.size());
  std::iota(target.begin(), target.end(), 0u);
  for (std::uint32_t v = 0; v < positions.size(); ++v) {
    if (v < first_new && !touched[v]) continue;
    const Key k = key(positions[v]);
    if (v >= first_new)
      for (std::int64_t dx = -1; dx <= 1 && target[v] == v; ++dx)
        for (std::int64_t dy = -1; dy <= 1 && target[v] == v; ++dy)
          for (std::int64_t dz = -1; dz <= 1 && target[v] == v; ++dz) {
            const auto bucket = grid.find({k[0] + dx, k[1] + dy, k[2] + dz});
            if (bucket == grid.end()) continue;
            for (std::uint32_t w : bucket->second)
              if ((positions[w] - positions[v]).norm() <= tolerance && normals[w].dot(normals[v]) >= 0.0) {
                target[v] = w;
                break;
              }
          }
    if (target[v] == v) grid[k].push_back(v);
  }
  std::size_t kept = 0;
  for (std::size_t t = 0; t < out.mesh.triangles.size(); ++t) {
    const Triangle& old = out.mesh.triangles[t];
    const Triangle w{target[old[0]], target[old[1]], target[old[2]]};
    if (w[0] == w[1] || w[1] == w[2] || w[2] == w[0]) continue;
    out.mesh.triangles[kept] = w;
    out.origin[kept] = out.origin[t];
    ++kept;
  }
  out.mesh.triangles.resize(kept);
  out.origin.resize(kept);
}

}  // namespace

ZoneCut cut_zone(const TriangleMesh& mesh, const std::vector<char>& zone, const std::vector<PlaneFamily>& families,
                 double tolerance, const PieceFilter& wanted) {
  ZoneCutter cutter(mesh, tolerance);
  std::vector<Piece> pieces;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    if (zone[t]) pieces.push_back({mesh.triangles[t], t});
  for (std::size_t f = 0; f < families.size(); ++f) cutter.cut(pieces, families[f], f, wanted);
  ZoneCut out;
  std::vector<Vec3> positions = cutter.positions();
  std::vector<char> touched(mesh.positions.size(), 0);  // corners of zone triangles
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    if (zone[t])
      for (std::uint32_t v : mesh.triangles[t]) touched[v] = 1;
  out.mesh.triangles.reserve(mesh.triangles.size() + 3 * pieces.size());
  out.origin.reserve(out.mesh.triangles.capacity());
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    if (zone[t]) continue;
    // Only an edge shared with a zone triangle (both ends touched) can have gained vertices.
    const Triangle& tri = mesh.triangles[t];
    if (touched[tri[0]] + touched[tri[1]] + touched[tri[2]] < 2) {
      out.mesh.triangles.push_back(tri);
      out.origin.push_back(t);
    } else {
      add_conforming(tri, cutter, positions, t, out);
    }
  }
  for (const Piece& p : pieces) add_conforming(p.corners, cutter, positions, p.origin, out);
  out.mesh.positions = std::move(positions);
  merge_coincident(out, static_cast<std::uint32_t>(mesh.positions.size()), touched, tolerance);
  if (mesh.has_materials()) {
    out.mesh.materials.reserve(out.origin.size());
    for (std::uint32_t t : out.origin) out.mesh.materials.push_back(mesh.materials[t]);
  }
  return out;
}

}  // namespace dg
