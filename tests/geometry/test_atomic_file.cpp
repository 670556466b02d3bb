// Output files written through a temporary file: what a failed write says.

#include "geometry/atomic_file.h"
#include "geometry/errors.h"

#include "support/cli_run.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

// The message write_file_atomically throws for `path`, or "" when it writes.
std::string write_error(const std::filesystem::path& path) {
  try {
    dg::write_file_atomically(path, [](std::ostream& out) { out << "data\n"; });
  } catch (const dg::InputError& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST_CASE("atomic file: a write lands whole and a failed one says why", "[geometry]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-atomic-file-test");
  CHECK(write_error(folder / "out.txt").empty());
  CHECK(std::filesystem::file_size(folder / "out.txt") == 5);
  // Only the finished file is left, no temporary one.
  CHECK(std::distance(std::filesystem::directory_iterator(folder), std::filesystem::directory_iterator()) == 1);

  const std::filesystem::path missing = folder / "missing" / "out.txt";
  CHECK(write_error(missing) == missing.string() + ": cannot open for writing: the folder " + (folder / "missing").string() +
                                    " does not exist");
  std::ofstream(folder / "taken") << "a file\n";
  const std::filesystem::path below_file = folder / "taken" / "out.txt";
  CHECK(write_error(below_file) == below_file.string() + ": cannot open for writing: " + (folder / "taken").string() +
                                       " is a file, not a folder");
}
