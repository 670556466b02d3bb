#pragma once
// The seam curve of a piece cut out of a mesh, and whether two seam curves coincide (so the
// piece cut at one location fits the hole left at another).

#include "geometry/mesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace dg {

using Segment = std::array<Vec3, 2>;

/// How far apart (fraction of the voxel size eps) two seam curves may lie and still fit, and
/// how close seam vertices of derived pieces are welded. Seams placed by fitted motions agree
/// only up to the float32 rounding of the source coordinates (the Kenney building-small-c:
/// 1e-8 to 7e-8 model units, up to 1e-5 eps), so 1e-6 eps rejected sites that fit; features on
/// a seam are far larger (eps / 100 and up). The same fraction welds grid seams
/// (kSeamWeldFraction).
inline constexpr double kSeamFitFraction = 1e-4;

/// For every triangle corner k of `mesh`, the triangle across edge (k, k+1), or -1 when that
/// edge is used by one triangle only or by more than two.
std::vector<std::int64_t> triangles_across(const TriangleMesh& mesh);

/// Edges between a flagged triangle (`inside`, one flag per triangle) and an unflagged one:
/// the curve along which the flagged piece was cut from the rest. Edges on the model's own
/// border are not part of it.
std::vector<Segment> seam_segments(const TriangleMesh& mesh, const std::vector<std::int64_t>& across,
                                   const std::vector<std::uint32_t>& piece, const std::vector<char>& inside);

/// True when every end and midpoint of each segment of `a` lies within `tolerance` (model
/// units) of a segment of `b` and the other way round. `cell` sizes the spatial hash (about
/// the segment length).
bool same_curve(const std::vector<Segment>& a, const std::vector<Segment>& b, double tolerance, double cell);

}  // namespace dg
