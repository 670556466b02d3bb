// messy_facade(columns, rows): facade(columns, rows) with the damage that real pipelines leave,
// on the same underlying shape and with the same repetitions:
//  - sliver triangles: 4 edges split by a point at 1e-6 of their length from one end, in both
//    triangles beside the edge (8 slivers of near-zero area, 4 new positions on existing edges);
//  - duplicated faces: 4 triangles get a back-to-back copy (same vertices, reversed order);
//  - a non-manifold fin: one extra triangle on an existing edge, its apex 0.25 m off the face
//    (1 new position);
//  - unwelded vertices: every triangle of the top face (z = height) gets its own three vertices
//    (duplicated positions, so the top face is cut loose by index).
// "damage" in the ground truth counts each; repetition unit measures refer to the clean facade.

#include "assets/generator/ground_truth.h"
#include "assets/generator/models.h"

#include <algorithm>
#include <fmt/format.h>
#include <map>

namespace dg::assets {

namespace {

constexpr double kSliverFraction = 1e-6;
constexpr double kFinHeight = 0.25;

/// Index of the triangle (other than `self`) that holds the directed edge b -> a.
std::size_t opposite_triangle(const TriangleMesh& mesh, std::size_t self, std::uint32_t a, std::uint32_t b) {
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      if (t != self && tri[static_cast<std::size_t>(k)] == b && tri[static_cast<std::size_t>((k + 1) % 3)] == a) return t;
    }
  }
  return self;
}

/// Replaces the triangle holding directed edge a -> b by two, split at vertex p on that edge.
void split_at(TriangleMesh& mesh, std::size_t t, std::uint32_t a, std::uint32_t b, std::uint32_t p) {
  Triangle tri = mesh.triangles[t];
  while (!(tri[0] == a && tri[1] == b)) tri = {tri[1], tri[2], tri[0]};
  mesh.triangles[t] = {a, p, tri[2]};
  mesh.triangles.push_back({p, b, tri[2]});
}

}  // namespace

Asset make_messy_facade(const nlohmann::json& params) {
  Asset asset = make_facade(params);
  TriangleMesh& mesh = asset.mesh;
  const double top = mesh.bounds().max.z();
  const nlohmann::json clean = mesh_statistics(mesh);

  // Candidates: triangles away from the top face, in index order; picks are spread over them.
  std::vector<std::size_t> candidates;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto c = mesh.corners(t);
    if (std::all_of(c.begin(), c.end(), [&](const Vec3& x) { return x.z() < top; })) candidates.push_back(t);
  }
  std::vector<char> touched(mesh.triangles.size(), 0);
  const auto pick = [&](std::size_t k, std::size_t of) {
    std::size_t i = candidates.size() * k / of;
    while (touched[candidates[i]]) i = (i + 1) % candidates.size();
    touched[candidates[i]] = 1;
    return candidates[i];
  };

  int slivers = 0, new_positions = 0;
  for (std::size_t k = 1; k < 8; k += 2) {
    const std::size_t t = pick(k, 8);
    const std::uint32_t a = mesh.triangles[t][0], b = mesh.triangles[t][1];
    const std::size_t other = opposite_triangle(mesh, t, a, b);
    touched[other] = 1;
    const auto p = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.push_back(mesh.positions[a] + kSliverFraction * (mesh.positions[b] - mesh.positions[a]));
    ++new_positions;
    split_at(mesh, t, a, b, p);      // a p c is the sliver
    split_at(mesh, other, b, a, p);  // p a d is the sliver
    slivers += 2;
  }

  int duplicates = 0;
  for (std::size_t k = 0; k < 8; k += 2) {
    const Triangle tri = mesh.triangles[pick(k, 8)];
    mesh.triangles.push_back({tri[2], tri[1], tri[0]});
    ++duplicates;
  }

  const std::size_t fin_base = pick(5, 16);
  const Triangle base = mesh.triangles[fin_base];
  const Vec3 normal = mesh.area_vector(fin_base).normalized();
  const auto apex = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.push_back(0.5 * (mesh.positions[base[0]] + mesh.positions[base[1]]) + kFinHeight * normal);
  ++new_positions;
  mesh.triangles.push_back({base[1], base[0], apex});

  int unwelded = 0;
  for (Triangle& tri : mesh.triangles) {
    if (std::all_of(tri.begin(), tri.end(), [&](std::uint32_t v) { return mesh.positions[v].z() == top; })) {
      for (std::uint32_t& v : tri) {
        const Vec3 copy = mesh.positions[v];
        mesh.positions.push_back(copy);
        v = static_cast<std::uint32_t>(mesh.positions.size() - 1);
        ++unwelded;
      }
    }
  }

  nlohmann::json& truth = asset.ground_truth;
  asset.name = fmt::format("messy_facade_{}x{}", truth["parameters"]["columns"].get<int>(), truth["parameters"]["rows"].get<int>());
  truth["name"] = asset.name;
  truth["generator"] = "messy_facade";
  truth.update(mesh_statistics(mesh));
  truth["clean"] = clean;
  truth["damage"] = {{"sliver_triangles", slivers},
                     {"duplicated_faces", duplicates},
                     {"fin_triangles", 1},
                     {"unwelded_vertices", unwelded},
                     {"new_positions", new_positions},
                     {"note", "unit_area / unit_vertices / cell_* of repetitions and grids refer to the clean facade"}};
  truth["description"] = "facade with pipeline damage: slivers, back-to-back duplicate faces, a non-manifold fin, "
                         "an unwelded top face";
  return asset;
}

}  // namespace dg::assets
