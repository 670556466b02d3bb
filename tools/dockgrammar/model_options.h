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

/// Registers --tolerance on a subcommand that detects symmetries: how far apart (in voxels, eps)
/// mapped geometry may lie from its image and still match.
void add_tolerance_option(CLI::App& command, double& tolerance_eps);

/// Symmetry detection options with that position tolerance for meshes (point clouds keep their
/// own, wider one unless the tolerance is wider still).
SymmetryOptions symmetry_options(double tolerance_eps);

/// Caps TBB's threads as --threads asks (the returned object must stay alive while working).
std::unique_ptr<tbb::global_control> limit_threads(int threads);

/// Progress shown on stderr when it is a terminal and --quiet is off; empty otherwise.
ProgressCallback stderr_progress(bool quiet);

/// Runs prepare_model with the options, progress and thread cap.
PreparedModel prepare(const ModelOptions& options);

}  // namespace dg::cli
