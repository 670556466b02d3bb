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

/// An empty folder `name`-PID in the system's temporary directory (removed first when present),
/// PID being the test process's, so two test runs at once never share a folder. It is removed
/// with its files when the test process ends, unless the environment sets
/// DOCKGRAMMAR_KEEP_TEST_FILES (to look at what a failing test wrote).
std::filesystem::path fresh_folder(const std::string& name);

/// What `dockgrammar analyze` left for the tests: its run and the grammar file it wrote.
struct AnalyzedModel {
  CliRun run;
  std::filesystem::path grammar;
};

/// Runs `dockgrammar analyze assets/models/STEM.obj -q OPTIONS -o FOLDER` (FOLDER created when
/// missing); the grammar is FOLDER/STEM.grammar.json.
AnalyzedModel analyze_model(const std::string& stem, const std::filesystem::path& folder, const std::string& options = "");

}  // namespace dg::test
