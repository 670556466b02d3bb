#include "support/cli_run.h"

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sys/wait.h>

namespace dg::test {

CliRun run_cli(const std::string& arguments, const std::filesystem::path& folder) {
  const std::filesystem::path log = folder / "log.txt";
  const std::string command = std::string(DOCKGRAMMAR_CLI) + " " + arguments + " > " + log.string() + " 2>&1";
  const int raw = std::system(command.c_str());
  std::ifstream in(log);
  std::string output((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, output};
}

}  // namespace dg::test
