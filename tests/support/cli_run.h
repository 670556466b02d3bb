#pragma once
// Running the dockgrammar program from end-to-end tests.

#include <filesystem>
#include <string>

namespace dg::test {

/// Exit status (-1 when it did not exit normally) and everything it printed.
struct CliRun {
  int status = -1;
  std::string output;
};

/// Runs `dockgrammar ARGUMENTS` with stdout and stderr captured in FOLDER/log.txt.
CliRun run_cli(const std::string& arguments, const std::filesystem::path& folder);

}  // namespace dg::test
