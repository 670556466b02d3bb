#include "tools/dockgrammar/model_options.h"
#include "tools/dockgrammar/number_checks.h"

#include <fmt/core.h>

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace dg::cli {

void add_model_options(CLI::App& command, ModelOptions& options) {
  command.add_option("MODEL", options.model_path,
                     "Model file: OBJ, OFF, PLY, STL, glTF (.gltf/.glb) or XYZ points")
      ->required();
  command.add_option("-r,--radius", options.prepare.r,
                     "Similarity radius r in model units (default: 1.6% of the longest bounding-box side)")
      ->check(non_negative_number());
  command.add_option("--voxel", options.prepare.eps, "Voxel size in model units (default: r/4)")
      ->check(non_negative_number());
  command.add_option("--sharp-angle", options.prepare.sharp_angle_degrees,
                     "Dihedral angle in degrees above which an edge is a feature edge")
      ->check(number_in(0.0, 180.0))
      ->capture_default_str();
  command.add_flag("--match-materials", options.prepare.match_materials,
                   "Symmetries must also map each material onto itself; material borders count as feature lines "
                   "(for patterns that exist only in materials, like windows painted on a flat wall)");
  command
      .add_option("--same-material", options.prepare.same_materials,
                  "Materials that count as one when matching, as a comma-separated list of names or * patterns "
                  "(repeat for more groups; implies --match-materials), e.g. 'glass*,blind1,blind2' for window "
                  "tints chosen at random")
      ->allow_extra_args(false);
  command.add_option("--threads", options.threads, "Worker threads (default: all cores)")->check(number_in(0, 4096));
  command.add_flag("-q,--quiet", options.quiet, "No progress on stderr");
  command.add_flag("--json", options.json, "Print machine-readable results on stdout");
}

void add_search_options(CLI::App& command, SearchOptions& options) {
  command
      .add_option("--tolerance", options.tolerance_eps,
                  "How far apart, in voxels (eps), mapped geometry may lie from its image and still count as a "
                  "copy: the default suits exact repeats; 0.2-0.3 finds repeats that were placed or modelled "
                  "a little unevenly (bars of a hand-made railing); larger values start to merge different shapes")
      ->check(number_in(0.01, 1.0))
      ->capture_default_str();
  command
      .add_option("--candidates", options.candidates,
                  "Symmetry candidates verified on the voxel surface, those whose feature-line ends agree most "
                  "often first; more finds motions of small parts among many repeats (each costs about as much "
                  "as one of the default ones; the report says how many went unverified)")
      ->check(number_in(std::size_t(1), std::size_t(100000)))
      ->capture_default_str();
}

SymmetryOptions symmetry_options(const SearchOptions& search) {
  SymmetryOptions options;
  options.region.offset_tolerance_eps = search.tolerance_eps;
  options.region.cloud_offset_tolerance_eps = std::max(options.region.cloud_offset_tolerance_eps, search.tolerance_eps);
  options.max_verified = search.candidates;
  return options;
}

std::unique_ptr<tbb::global_control> limit_threads(int threads) {
  if (threads <= 0) return nullptr;
  return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                               static_cast<std::size_t>(threads));
}

ProgressCallback stderr_progress(bool quiet) {
  if (quiet || !::isatty(STDERR_FILENO)) return {};
  return [](std::string_view stage, double fraction) {
    fmt::print(stderr, "\r\033[K{:>3.0f}% {}", 100.0 * fraction, stage);
    if (fraction >= 1.0) fmt::print(stderr, "\n");
    std::fflush(stderr);
    return true;
  };
}

PreparedModel prepare(const ModelOptions& options) {
  const auto threads = limit_threads(options.threads);
  return prepare_model(options.model_path, options.prepare, stderr_progress(options.quiet));
}

}  // namespace dg::cli
