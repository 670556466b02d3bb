#pragma once
// Internal: one writer per output format, streaming a complete file into `out`.
// model_io.cpp checks the arguments and wraps these in write_file_atomically.

#include "geometry/mesh.h"
#include "geometry/model_io.h"

#include <bit>
#include <cstring>
#include <ostream>
#include <string>
#include <vector>

namespace dg::detail {

/// OBJ text: "v x y z" with shortest round-trip decimals, then "f a b c" (1-based).
void write_obj(std::ostream& out, const TriangleMesh& mesh);
/// PLY binary little endian: double x y z (+ uchar red green blue), uchar/uint vertex_indices lists.
void write_ply(std::ostream& out, const TriangleMesh& mesh, const std::vector<Rgb>* colors);
/// glTF 2.0 binary: one scene, one node, one mesh; float32 POSITION with min/max, optional
/// COLOR_0 (normalized unsigned bytes), uint32 indices.
void write_glb(std::ostream& out, const TriangleMesh& mesh, const std::vector<Rgb>* colors);

/// Appends the little-endian bytes of an integer or floating-point value to `bytes`.
template <typename T>
void append_le(std::string& bytes, T value) {
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) {
    for (std::size_t i = sizeof(T); i-- > 0;) bytes.push_back(static_cast<char>(raw[i]));
  } else {
    bytes.append(reinterpret_cast<const char*>(raw), sizeof(T));
  }
}

}  // namespace dg::detail
