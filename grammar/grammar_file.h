#pragma once
// The grammar file written by `analyze` and read by `generate`/`resize`: versioned JSON with
// sidecar piece meshes (binary PLY) in a folder next to it. Documented in docs/grammar-file.md.

#include "grammar/context_free.h"
#include "grammar/grid_rules.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace dg {

inline constexpr int kGrammarFileVersion = 3;  ///< versions 1 (grids only) and 2 (planar seams) are still read

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
  /// The exemplar's up axis for pictures, "x", "y" or "z" as given to `analyze --up`; empty
  /// when not given (pictures then guess it).
  std::string up_axis;
  std::vector<GridWithPieces> grids;
  ContextFreeGrammar context_free;  ///< empty when no docking site gave a production
  /// The exemplar's cleaned mesh (used when no grid is resized and for reference).
  TriangleMesh exemplar;
  /// The exemplar's materials, indexed by the materials of the exemplar and of every piece and
  /// terminal; empty when the exemplar names none.
  std::vector<Material> materials;
};

/// Hex FNV-1a 64-bit hash of a file's bytes (throws InputError when unreadable).
std::string file_hash(const std::filesystem::path& path);

/// Writes `grammar` to `path` (JSON) and its meshes to the folder `path` minus ".json" plus
/// ".pieces/", every file atomically.
void write_grammar(const std::filesystem::path& path, const ShapeGrammar& grammar);

/// Reads a grammar file and its sidecar meshes. Throws InputError naming the file and the
/// problem: unreadable, not JSON, wrong version, missing field, missing or broken sidecar.
ShapeGrammar read_grammar(const std::filesystem::path& path);

}  // namespace dg
