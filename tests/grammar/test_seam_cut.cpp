#include "grammar/seam_cut.h"

#include <catch2/catch.hpp>

#include <algorithm>

namespace {

// A voxel seam (eps 1) of faces across x on plane x = 5, at the given (j, l) = (y, z) squares.
dg::SeamSurface seam_on_plane_x5(const std::vector<std::array<std::int32_t, 2>>& squares) {
  dg::SeamSurface seam;
  seam.kind = dg::SeamSurface::Kind::voxel_faces;
  seam.eps = 1.0;
  for (const auto& [y, z] : squares) {
    dg::VoxelFace face;
    face.axis = 0;
    face.voxel = {5, y, z};
    seam.faces.push_back(face);
  }
  std::sort(seam.faces.begin(), seam.faces.end());
  return seam;
}

}  // namespace

TEST_CASE("seam face index: range queries per plane", "[grammar][voxel_seam]") {
  const dg::SeamFaceIndex index(seam_on_plane_x5({{2, 3}, {2, 9}, {7, 1}}));
  auto any = [](std::int64_t, std::int64_t) { return true; };
  CHECK(index.any_in(0, 5, 0, 10, 0, 10, any));
  CHECK(index.any_in(0, 5, 2, 2, 4, 9, any));       // row 2, column 9
  CHECK_FALSE(index.any_in(0, 5, 2, 2, 4, 8, any)); // row 2 holds columns 3 and 9 only
  CHECK_FALSE(index.any_in(0, 5, 3, 6, 0, 10, any));
  CHECK_FALSE(index.any_in(0, 4, 0, 10, 0, 10, any));  // another plane
  CHECK_FALSE(index.any_in(1, 5, 0, 10, 0, 10, any));  // another axis
  // The predicate sees every face in range, row by row.
  std::vector<std::array<std::int64_t, 2>> seen;
  CHECK_FALSE(index.any_in(0, 5, 0, 10, 0, 10, [&](std::int64_t j, std::int64_t l) {
    seen.push_back({j, l});
    return false;
  }));
  CHECK(seen == std::vector<std::array<std::int64_t, 2>>{{2, 3}, {2, 9}, {7, 1}});
}

TEST_CASE("crosses_face: a piece is cut where the seam passes through it, not where its box holds a face",
          "[grammar][voxel_seam]") {
  // One face on plane x = 5 at y in [2, 3], z in [3, 4].
  const dg::SeamFaceIndex index(seam_on_plane_x5({{2, 3}}));
  // A large triangle in the plane z = 3.5 whose chord at x = 5 runs over y in [0, 5]: it meets the face.
  const std::array<dg::Vec3, 3> through{dg::Vec3(0, 0, 3.5), dg::Vec3(10, 0, 3.5), dg::Vec3(5, 10, 3.5)};
  CHECK(dg::crosses_face(index, through, 0, 5));
  CHECK_FALSE(dg::crosses_face(index, through, 0, 4));  // no face on that plane
  // A triangle whose box covers the face but whose chord at x = 5 stays at y in [5, 10] (z = 3.5).
  const std::array<dg::Vec3, 3> beside{dg::Vec3(0, 10, 3.5), dg::Vec3(10, 10, 3.5), dg::Vec3(0, 0, 3.5)};
  CHECK_FALSE(dg::crosses_face(index, beside, 0, 5));
  // A tilted triangle whose chord passes diagonally next to the face, then through it.
  const std::array<dg::Vec3, 3> diagonal{dg::Vec3(0, 0, 10), dg::Vec3(10, 0, 10), dg::Vec3(5, 10, 0)};
  CHECK_FALSE(dg::crosses_face(index, diagonal, 0, 5));  // chord y + z = 10 misses [2, 3] x [3, 4]
  const std::array<dg::Vec3, 3> diagonal_through{dg::Vec3(0, 0, 5.5), dg::Vec3(10, 0, 5.5), dg::Vec3(5, 5.5, 0)};
  CHECK(dg::crosses_face(index, diagonal_through, 0, 5));  // chord y + z = 5.5 crosses it
  // A chord that ends on the face's border counts (seam edges on piece borders must exist too).
  const std::array<dg::Vec3, 3> touching{dg::Vec3(0, 3, 3.5), dg::Vec3(10, 3, 3.5), dg::Vec3(5, 8, 3.5)};
  CHECK(dg::crosses_face(index, touching, 0, 5));
}
