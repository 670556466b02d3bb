#pragma once
// The grammar file written by `analyze` and read by `generate`/`resize`: versioned JSON with
// sidecar piece meshes (binary PLY) in a folder next to it. Documented in docs/grammar-file.md.

#include "grammar/context_free.h"
#include "grammar/grid_cut.h"
#include "grammar/grid_rules.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace dg {

/// Versions 1 (grids only), 2 (planar seams), 3 (no point-cloud exemplars) and 4 (point-cloud
/// grammars without context-free rules) are still read.
inline constexpr int kGrammarFileVersion = 5;

/// A grid rule with its pieces and where they are stored.
struct GridWithPieces {
  GridRule rule;
  std::vector<GridPiece> pieces;
};

/// Everything `analyze` writes and `resize`/`generate` read: the rules with their pieces.
struct ShapeGrammar {
  std::string source_name;    ///< file name of the exemplar
  std::string source_hash;    ///< FNV-1a 64-bit hash of the exemplar file's bytes, hex
  double r = 0.0, eps = 0.0;  ///< model units
  /// Where the source file's coordinates put the grammar's origin (PreparedModel::origin): the
  /// exemplar, pieces, seams and motions are stored moved by -origin, and resize and generate
  /// move what they build back by +origin. Zero unless the model lay beyond the voxel grid's reach.
  Vec3 origin = Vec3::Zero();
  /// The exemplar's up axis for pictures, "x", "y" or "z" as given to `analyze --up`; empty
  /// when not given (pictures then guess it).
  std::string up_axis;
  std::vector<GridWithPieces> grids;
  ContextFreeGrammar context_free;  ///< empty when no docking site gave a production
  /// The exemplar's cleaned mesh (used when no grid is resized and for reference); empty when
  /// the exemplar is a point cloud.
  TriangleMesh exemplar;
  /// The exemplar's points when it is a point cloud (then every grid piece holds points too).
  PointCloud exemplar_points;
  /// The exemplar's materials, indexed by the materials of the exemplar and of every piece and
  /// terminal; empty when the exemplar names none.
  std::vector<Material> materials;
};

/// True when the grammar was made from a point cloud: its exemplar and pieces are points.
inline bool is_point_grammar(const ShapeGrammar& grammar) {
  return grammar.exemplar.triangles.empty() && !grammar.exemplar_points.positions.empty();
}

/// Bounding box of the grammar's exemplar (its mesh, or its points for a point-cloud grammar).
inline BoundingBox exemplar_bounds(const ShapeGrammar& grammar) {
  return is_point_grammar(grammar) ? grammar.exemplar_points.bounds() : grammar.exemplar.bounds();
}

/// The motion from the grammar's frame to the source file's coordinates: translation by origin.
inline RigidTransform to_source_frame(const ShapeGrammar& grammar) {
  RigidTransform motion;
  motion.translation = grammar.origin;
  return motion;
}

/// Hex FNV-1a 64-bit hash of a file's bytes (throws InputError when unreadable).
std::string file_hash(const std::filesystem::path& path);

/// Writes `grammar` to `path` (JSON) and its meshes to the folder `path` minus ".json" plus
/// ".pieces/", every file atomically.
void write_grammar(const std::filesystem::path& path, const ShapeGrammar& grammar);

/// Reads a grammar file and its sidecar meshes. Throws InputError naming the file and the
/// problem: unreadable, not JSON, wrong version, missing field, missing or broken sidecar.
ShapeGrammar read_grammar(const std::filesystem::path& path);

}  // namespace dg
