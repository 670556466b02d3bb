// `dockgrammar analyze MODEL`: the full analysis. The stages after the voxel surface and the
// feature lines (symmetry detection, docking sites, grammar rules) are not built yet; the
// command runs what exists and says where it stopped.

#include "tools/dockgrammar/commands.h"
#include "tools/dockgrammar/model_options.h"
#include "tools/dockgrammar/model_summary.h"

#include <fmt/core.h>

#include <cstdio>
#include <memory>

namespace dg::cli {

namespace {
constexpr const char* kStoppedAfter =
    "analyze stopped after loading, cleaning, feature lines and the voxel surface: symmetry detection, "
    "docking sites and grammar rules are not implemented yet, so no grammar file was written";
}

void add_analyze_command(CLI::App& app) {
  auto options = std::make_shared<ModelOptions>();
  CLI::App* command = app.add_subcommand("analyze", "Find the rules that build a model (currently: the stages up to the voxel surface)");
  add_model_options(*command, *options);
  command->callback([options] {
    const PreparedModel prepared = prepare(*options);
    if (options->json) {
      nlohmann::json summary = summary_json(prepared);
      summary["completed"] = false;
      summary["note"] = kStoppedAfter;
      fmt::print("{}\n", summary.dump(2));
    } else {
      fmt::print("{}", summary_text(prepared));
    }
    fmt::print(stderr, "dockgrammar: {}\n", kStoppedAfter);
  });
}

}  // namespace dg::cli
