// `dockgrammar info MODEL`: the cleaning report, voxel-surface statistics and stage timings.

#include "tools/dockgrammar/commands.h"
#include "tools/dockgrammar/model_options.h"
#include "tools/dockgrammar/model_summary.h"

#include <fmt/core.h>

#include <memory>

namespace dg::cli {

void add_info_command(CLI::App& app) {
  auto options = std::make_shared<ModelOptions>();
  CLI::App* command = app.add_subcommand("info", "Load a model and report its cleaning, voxel surface and feature lines");
  add_model_options(*command, *options);
  command->callback([options] {
    const PreparedModel prepared = prepare(*options);
    if (options->json)
      fmt::print("{}\n", summary_json(prepared).dump(2));
    else
      fmt::print("{}", summary_text(prepared));
  });
}

}  // namespace dg::cli
