#pragma once
// Offscreen pictures of meshes: flat-coloured, shaded triangles with optional outlines and
// overlay curves (docking sites, feature lines), like figure 1b of the 3D paper.

#include "geometry/camera.h"
#include "geometry/image.h"
#include "geometry/mesh.h"

#include <filesystem>
#include <vector>

namespace dg {

/// How a mesh picture looks.
struct MeshRenderOptions {
  int width = 960;   ///< picture width in pixels, 1..16384
  int height = 720;  ///< picture height in pixels, 1..16384
  /// View direction (azimuth/elevation around the up axis, default y-up), projection and
  /// margin; the camera is fitted so that the whole model and all lines are visible.
  CameraSetup camera;
  /// Samples per pixel along each axis, 1..8; the samples are averaged (box filter).
  /// width x height x supersample^2 may not exceed 2^28.
  int supersample = 2;
  Rgba8 background{255, 255, 255, 255};
  /// Colour of every triangle when no per-triangle colours are given.
  Rgba8 default_color{200, 200, 200, 255};
  /// Dark outlines where the surface meets the background, where the depth jumps between two
  /// triangles, and at creases (neighbouring visible normals differing by more than crease_degrees).
  bool draw_edges = true;
  double crease_degrees = 40;
  Rgba8 edge_color{45, 45, 45, 255};
  /// Depth-tested lines count as visible up to this distance behind the surface, as a fraction
  /// of the bounding-box diagonal, so curves lying on the surface are not hidden by it.
  double line_depth_bias = 0.01;
};

/// An overlay curve in model coordinates, drawn over the shaded mesh.
struct SceneLine {
  std::vector<Vec3> points;  ///< polyline corners; one point draws a dot
  Rgba8 color{0, 0, 0, 255};
  double width_pixels = 2;   ///< line width in output pixels
  bool depth_test = true;    ///< false: drawn on top even where the mesh hides it
};

/// Renders `mesh` into a picture of options.width x options.height pixels.
/// `triangle_colors` holds one colour per triangle (alpha ignored) or is empty (default_color).
/// Shading: two-sided Lambert with ambient under a light near the viewer (somewhat from the left
/// and a little from above), so back faces and inverted normals look like front faces. `lines` are drawn in order
/// on top, anti-aliased, each hidden where the mesh is nearer (unless depth_test is false).
/// An empty mesh gives the background (plus the lines). The output is byte-identical for equal
/// input with any thread count. Throws InputError for out-of-range options, a colour count that
/// does not match the triangles, a corner index out of range, or non-finite coordinates.
Image render_mesh(const TriangleMesh& mesh, const std::vector<Rgba8>& triangle_colors,
                  const std::vector<SceneLine>& lines, const MeshRenderOptions& options = {});

/// A 2 x 2 contact sheet of options.width x options.height pixels: front (azimuth 0, elevation
/// 0), right side (90, 0), top (0, 90) and the options' own view, left to right, top to bottom.
/// Each view is fitted to its own cell. Throws like render_mesh.
Image render_views(const TriangleMesh& mesh, const std::vector<Rgba8>& triangle_colors,
                   const std::vector<SceneLine>& lines, const MeshRenderOptions& options = {});

/// Renders like render_mesh and writes the picture as a PNG through a temporary file renamed
/// into place. Throws InputError as render_mesh does and when the file cannot be written.
void write_mesh_picture(const std::filesystem::path& png, const TriangleMesh& mesh,
                        const std::vector<Rgba8>& triangle_colors, const std::vector<SceneLine>& lines = {},
                        const MeshRenderOptions& options = {});

}  // namespace dg
