#pragma once
// Internal: one reader per file format. Each gets the whole file in memory and the path (for
// messages and for files the format refers to, like glTF buffers) and returns the raw model:
// polygons triangulated inside their outlines (geometry/polygon_triangulation.h), nothing welded
// or validated beyond the format itself.
// model_io.cpp picks the reader by extension and checks the result (finite, in range, not empty).

#include "geometry/mesh.h"
#include "geometry/polygon_triangulation.h"

#include <algorithm>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace dg::detail {

/// Wavefront OBJ: v / f lines (n-gons, negative indices, v/vt/vn forms, '\' continuation), and
/// usemtl materials with their Kd colours from the mtllib files next to `path`.
Model read_obj(const std::filesystem::path& path, std::string_view text);
/// OFF (also COFF/NOFF/CNOFF/STOFF headers): vertex and polygon lists.
Model read_off(const std::string& name, std::string_view text);
/// PLY ascii or binary (either endianness); no faces gives a point cloud.
Model read_ply(const std::string& name, std::string_view bytes);
/// STL ascii or binary (binary recognised by its size formula); an unwelded triangle soup.
Model read_stl(const std::string& name, std::string_view bytes);
/// glTF 2.0, JSON (.gltf, external or data: buffers) or binary (.glb): every mesh instance of the
/// default scene with its node transforms applied.
Model read_gltf(const std::filesystem::path& path, std::string_view bytes, bool binary);
/// XYZ text points: "x y z" or "x y z nx ny nz" per line.
Model read_xyz(const std::string& name, std::string_view text);

/// Polygons of more than three corners, noted while reading: their positions may come later in
/// the file, so they are triangulated once the file is read and its indices are checked.
struct PolygonFaces {
  std::vector<std::size_t> first_triangle;  ///< each polygon's first triangle in the mesh
  std::vector<std::size_t> corner_start;    ///< each polygon's first corner in `corners`
  std::vector<std::uint32_t> corners;
};

/// Appends a polygon's n - 2 triangles to `mesh` as its fan (c0 c1 c2), (c0 c2 c3), ..., noting
/// polygons of more than three corners in `polygons`.
inline void add_polygon(TriangleMesh& mesh, const std::uint32_t* corners, std::size_t count, PolygonFaces& polygons) {
  if (count > 3) {
    polygons.first_triangle.push_back(mesh.triangles.size());
    polygons.corner_start.push_back(polygons.corners.size());
    polygons.corners.insert(polygons.corners.end(), corners, corners + count);
  }
  const std::vector<Triangle> triangles = fan(std::span<const std::uint32_t>(corners, count));
  mesh.triangles.insert(mesh.triangles.end(), triangles.begin(), triangles.end());
}

/// Replaces each noted polygon's fan by triangulate_polygon's triangles (the same count, so
/// per-triangle data stays aligned). Every corner index must be valid.
inline void triangulate_polygons(TriangleMesh& mesh, const PolygonFaces& polygons) {
  for (std::size_t p = 0; p < polygons.first_triangle.size(); ++p) {
    const std::size_t begin = polygons.corner_start[p];
    const std::size_t end = p + 1 < polygons.corner_start.size() ? polygons.corner_start[p + 1] : polygons.corners.size();
    const std::vector<Triangle> triangles =
        triangulate_polygon(mesh.positions, std::span<const std::uint32_t>(polygons.corners.data() + begin, end - begin));
    std::copy(triangles.begin(), triangles.end(), mesh.triangles.begin() + static_cast<std::ptrdiff_t>(polygons.first_triangle[p]));
  }
}

}  // namespace dg::detail
