#pragma once
// Point clouds drawn with the mesh renderer: every point becomes a small solid (a splat).

#include "geometry/image.h"
#include "geometry/mesh.h"
#include "geometry/render_mesh.h"

#include <filesystem>
#include <vector>

namespace dg {

/// Points drawn per picture at most: larger clouds are thinned to every k-th point (k the
/// smallest stride that keeps at most this many), which a picture of about 1000 pixels across
/// cannot tell apart.
inline constexpr std::size_t kMaxDrawnPoints = 300'000;

/// Splat radius for pictures of clouds made with voxel size eps: kSplatRadius * eps.
inline constexpr double kSplatRadius = 0.4;

/// A mesh of one octahedron of circumradius `radius` (model units) around each drawn point of
/// `points` (every point, or every k-th, see kMaxDrawnPoints), and the colour of each of its
/// triangles from `point_colors` (one per point, or empty: no colours).
struct PointSplats {
  TriangleMesh mesh;
  std::vector<Rgba8> triangle_colors;
};
PointSplats point_splats(const std::vector<Vec3>& points, const std::vector<Rgba8>& point_colors, double radius);

/// Writes a PNG of `points` drawn as splats of `radius` (point_splats), coloured by
/// `point_colors` (one per point, or empty: the default colour), with the options of a mesh
/// picture (outlines are left out: they would outline every splat). Throws as write_mesh_picture.
void write_points_picture(const std::filesystem::path& png, const std::vector<Vec3>& points,
                          const std::vector<Rgba8>& point_colors, double radius, MeshRenderOptions options);

}  // namespace dg
