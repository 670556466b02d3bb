// The `dockgrammar` command line: parses the subcommand and maps errors to exit statuses
// (0 success, 1 internal failure, 2 bad input or usage).

#include "tools/dockgrammar/commands.h"

#include "geometry/errors.h"

#include <fmt/core.h>

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace {

// A usage error's message and where to read more: a missing or unknown command word is named
// with the commands there are (CLI11 only says that one is required), other messages stay CLI11's.
std::string usage_error_text(CLI::App& app, const CLI::ParseError& error, int argc, char** argv) {
  const std::vector<CLI::App*> chosen = app.get_subcommands();
  if (chosen.empty() && (argc == 1 || argv[1][0] != '-')) {
    std::string names;
    for (const CLI::App* command : app.get_subcommands([](CLI::App*) { return true; }))
      names += (names.empty() ? "" : ", ") + command->get_name();
    const std::string problem = argc == 1 ? std::string("no command given") : fmt::format("unknown command '{}'", argv[1]);
    return fmt::format("{} (commands: {})\nRun 'dockgrammar --help' for what each does.", problem, names);
  }
  std::string command = "dockgrammar";
  for (CLI::App* level = &app; !level->get_subcommands().empty();) {
    level = level->get_subcommands().back();
    command += " " + level->get_name();
  }
  return fmt::format("{}\nRun '{} --help' for the options.", error.what(), command);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"dockgrammar: inverse procedural modeling from one example model"};
  app.set_version_flag("--version", std::string("dockgrammar ") + DOCKGRAMMAR_VERSION);
  app.require_subcommand(1);
  dg::cli::add_info_command(app);
  dg::cli::add_analyze_command(app);
  dg::cli::add_symmetry_command(app);
  dg::cli::add_resize_command(app);
  dg::cli::add_generate_command(app);
  dg::cli::add_lsystem_command(app);
  dg::cli::add_verify_command(app);
  dg::cli::add_grow_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::RuntimeError& e) {  // a command's own status, e.g. verify: 1 when a check fails
    return e.get_exit_code();
  } catch (const CLI::ParseError& e) {
    fmt::print(stderr, "dockgrammar: {}\n", usage_error_text(app, e, argc, argv));
    return 2;
  } catch (const dg::InputError& e) {
    fmt::print(stderr, "dockgrammar: {}\n", e.what());
    return 2;
  } catch (const dg::LimitError& e) {
    fmt::print(stderr, "dockgrammar: {}\n", e.what());
    return 2;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "dockgrammar: out of memory\n");
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "dockgrammar: internal error: {}\n", e.what());
    return 1;
  }
  return 0;
}
