#include "assets/generator/mesh_builder.h"

#include <bit>

namespace dg::assets {

std::size_t MeshBuilder::KeyHash::operator()(const Vec3& p) const {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (int axis = 0; axis < 3; ++axis) {
    // Adding +0.0 turns -0.0 into +0.0, so both hash alike (they compare equal).
    h ^= std::bit_cast<std::uint64_t>(p[axis] + 0.0);
    h *= 0x100000001b3ULL;
    h ^= h >> 29;
  }
  return static_cast<std::size_t>(h);
}

std::uint32_t MeshBuilder::vertex(const Vec3& p) {
  const auto [it, inserted] = index_.try_emplace(p, static_cast<std::uint32_t>(mesh_.positions.size()));
  if (inserted) mesh_.positions.push_back(p + Vec3::Zero());
  return it->second;
}

void MeshBuilder::triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  mesh_.triangles.push_back({vertex(a), vertex(b), vertex(c)});
}

void MeshBuilder::quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  triangle(a, b, c);
  triangle(a, c, d);
}

TriangleMesh MeshBuilder::take() {
  index_.clear();
  TriangleMesh result = std::move(mesh_);
  mesh_ = TriangleMesh{};
  return result;
}

}  // namespace dg::assets
