#pragma once
// Options shared by the subcommands that read one model: the path, r, voxel size, threads,
// quiet and JSON switches, and the stderr progress display.

#include "geometry/errors.h"
#include "geometry/prepared_model.h"
#include "symmetry/symmetry_detection.h"

#include <CLI/CLI.hpp>
#include <tbb/global_control.h>

#include <memory>
#include <string>

namespace dg::cli {

struct ModelOptions {
  std::string model_path;
  PrepareOptions prepare;
  int threads = 0;  ///< 0 = all cores
  bool quiet = false;
  bool json = false;
};

/// Registers MODEL, -r, --voxel, --sharp-angle, --threads, --quiet and --json on a subcommand.
void add_model_options(CLI::App& command, ModelOptions& options);

/// How a subcommand that detects symmetries searches: the matching tolerance and how many
/// candidates it verifies.
struct SearchOptions {
  /// How far apart (in voxels, eps) mapped geometry may lie from its image and still match.
  double tolerance_eps = RegionOptions{}.offset_tolerance_eps;
  std::size_t candidates = SymmetryOptions{}.max_verified;  ///< candidates verified, best supported first
};

/// Registers --tolerance and --candidates on a subcommand that detects symmetries.
void add_search_options(CLI::App& command, SearchOptions& options);

/// Symmetry detection options for a search: its position tolerance for meshes (point clouds keep
/// their own, wider one unless the tolerance is wider still) and its number of candidates verified.
SymmetryOptions symmetry_options(const SearchOptions& search);

/// Caps TBB's threads as --threads asks (the returned object must stay alive while working).
std::unique_ptr<tbb::global_control> limit_threads(int threads);

/// Progress shown on stderr when it is a terminal and --quiet is off; empty otherwise.
ProgressCallback stderr_progress(bool quiet);

/// Runs prepare_model with the options, progress and thread cap.
PreparedModel prepare(const ModelOptions& options);

}  // namespace dg::cli
