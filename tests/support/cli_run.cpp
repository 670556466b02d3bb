#include "support/cli_run.h"

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <system_error>
#include <vector>
#include <sys/wait.h>
#include <unistd.h>

namespace dg::test {
namespace {

// The folders fresh_folder made, removed with their files when the test process ends, unless
// DOCKGRAMMAR_KEEP_TEST_FILES is set (to look at a failing test's files).
struct MadeFolders {
  std::vector<std::filesystem::path> folders;
  MadeFolders() = default;
  MadeFolders(const MadeFolders&) = delete;
  MadeFolders& operator=(const MadeFolders&) = delete;
  ~MadeFolders() {
    if (std::getenv("DOCKGRAMMAR_KEEP_TEST_FILES")) return;
    std::error_code ignored;
    for (const std::filesystem::path& folder : folders) std::filesystem::remove_all(folder, ignored);
  }
};

MadeFolders& made_folders() {
  static MadeFolders made;
  return made;
}

}  // namespace

CliRun run_cli(const std::string& arguments, const std::filesystem::path& folder) {
  const std::filesystem::path log = folder / "log.txt";
  const std::string command = std::string(DOCKGRAMMAR_CLI) + " " + arguments + " > " + log.string() + " 2>&1";
  const int raw = std::system(command.c_str());
  std::ifstream in(log);
  std::string output((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, output};
}

std::filesystem::path fresh_folder(const std::string& name) {
  // One folder per test process: test runs of two checkouts at once do not share files.
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  made_folders().folders.push_back(folder);
  return folder;
}

AnalyzedModel analyze_model(const std::string& stem, const std::filesystem::path& folder, const std::string& options) {
  std::filesystem::create_directories(folder);
  const std::string model = std::string(DOCKGRAMMAR_SOURCE_DIR) + "/assets/models/" + stem + ".obj";
  AnalyzedModel analyzed;
  analyzed.run = run_cli("analyze " + model + " -q " + options + " -o " + folder.string(), folder);
  analyzed.grammar = folder / (stem + ".grammar.json");
  return analyzed;
}

}  // namespace dg::test
