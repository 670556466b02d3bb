// `dockgrammar verify EXEMPLAR CANDIDATE`: closedness, self-intersections and r-similarity of a
// generated model against its exemplar. Exit status 0 when every check passes, 1 when one fails.

#include "synthesis/verify.h"
#include "tools/dockgrammar/commands.h"
#include "tools/dockgrammar/model_options.h"
#include "tools/dockgrammar/number_checks.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <memory>
#include <string>

namespace dg::cli {

void add_verify_command(CLI::App& app) {
  struct Options {
    std::string exemplar, candidate;
    VerifyOptions verify;
    int threads = 0;
    bool quiet = false;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "verify",
      "Check a generated model against its exemplar: closed, no self-intersections, r-similar (a point's "
      "r-neighbourhood is the surface inside the r-ball that is connected to the point within the ball, an "
      "intrinsic neighbourhood as in Bokeloh et al. 2010 sec. 3.1; it must match the exemplar's under a rigid "
      "motion, both ways). Two point clouds (PLY without faces, XYZ) get the r-similarity check, each point "
      "standing for a small disk in its tangent plane (normals fitted when the file has none)");
  command->add_option("EXEMPLAR", options->exemplar, "The exemplar model file")->required();
  command->add_option("CANDIDATE", options->candidate, "The model to check")->required();
  command->add_option("-r,--radius", options->verify.r,
                      "Similarity radius r in model units (default: 1.6% of the exemplar's longest bounding-box side)")
      ->check(non_negative_number());
  command->add_option("--samples", options->verify.similarity.samples, "Test points on the candidate")
      ->check(number_in(std::size_t{1}, std::size_t{100'000'000}))
      ->capture_default_str();
  command->add_option("--seed", options->verify.similarity.seed, "Seed of the test points")->capture_default_str()->check(seed_number());
  command->add_option("--min-fraction", options->verify.min_similar_fraction,
                      "Smallest r-similar fraction that passes")
      ->check(number_in(0.0, 1.0))
      ->capture_default_str();
  command->add_option("--threads", options->threads, "Worker threads (default: all cores)")->check(number_in(0, 4096));
  command->add_flag("-q,--quiet", options->quiet, "No progress on stderr");
  command->add_flag("--json", options->json, "Print machine-readable results on stdout");
  command->callback([options] {
    const auto threads = limit_threads(options->threads);
    const VerifyReport report =
        verify_models(options->exemplar, options->candidate, options->verify, stderr_progress(options->quiet));
    if (options->json)
      fmt::print("{}\n", to_json(report).dump(2));
    else
      fmt::print("{}", to_text(report));
    if (!report.pass) throw CLI::RuntimeError(1);  // status 1: a check failed
  });
}

}  // namespace dg::cli
