#pragma once
// Internal: one reader per file format. Each gets the whole file in memory and the path (for
// messages and for files the format refers to, like glTF buffers) and returns the raw model:
// polygons fan-triangulated, nothing welded or validated beyond the format itself.
// model_io.cpp picks the reader by extension and checks the result (finite, in range, not empty).

#include "geometry/mesh.h"

#include <filesystem>
#include <string>
#include <string_view>

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

/// Appends the fan triangulation (c0 c1 c2), (c0 c2 c3), ... of a polygon to `mesh`.
inline void add_fan(TriangleMesh& mesh, const std::uint32_t* corners, std::size_t count) {
  for (std::size_t i = 1; i + 1 < count; ++i) mesh.triangles.push_back({corners[0], corners[i], corners[i + 1]});
}

}  // namespace dg::detail
