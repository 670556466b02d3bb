// Out-of-range numbers on the command line and output folders that cannot be made: one short
// error with exit status 2.

#include "support/cli_run.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <string>

TEST_CASE("options: negative, infinite and oversized numbers are usage errors with short messages", "[tools]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-option-errors-test");
  const std::string model = std::string(DOCKGRAMMAR_SOURCE_DIR) + "/assets/models/fence_4.obj";
  auto run = [&](const std::string& arguments) { return dg::test::run_cli(arguments, folder); };

  const dg::test::CliRun negative = run("info " + model + " -q -r -1");
  CHECK(negative.status == 2);
  CHECK(negative.output.find("--radius: must be 0 or more, got -1") != std::string::npos);
  CHECK(negative.output.size() < 200);  // no range printed up to the largest double

  const dg::test::CliRun infinite = run("info " + model + " -q --voxel inf");
  CHECK(infinite.status == 2);
  CHECK(infinite.output.find("'inf' is not a finite number") != std::string::npos);

  const dg::test::CliRun zero_top = run("symmetry " + model + " -q --top 0");
  CHECK(zero_top.status == 2);
  CHECK(zero_top.output.find("--top: expected a whole number from 1 to 100000, got '0'") != std::string::npos);

  const dg::test::CliRun no_tolerance = run("symmetry " + model + " -q --tolerance 0");
  CHECK(no_tolerance.status == 2);
  CHECK(no_tolerance.output.find("--tolerance: expected a number from 0.01 to 1, got '0'") != std::string::npos);

  // A voxel larger than the radius leaves no r-neighbourhood to compare.
  const dg::test::CliRun coarse = run("analyze " + model + " -q -r 0.1 --voxel 0.5 -o " + (folder / "out").string());
  CHECK(coarse.status == 2);
  CHECK(coarse.output.find("voxel size 0.5 is larger than the radius r = 0.1") != std::string::npos);
  std::filesystem::remove_all(folder);
}

TEST_CASE("options: words, signs and overflow where a whole number belongs, and unknown commands, are one clear error",
          "[tools]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-usage-errors-test");
  const std::string model = std::string(DOCKGRAMMAR_SOURCE_DIR) + "/assets/models/fence_4.obj";
  auto run = [&](const std::string& arguments) { return dg::test::run_cli(arguments, folder); };
  // Each message starts with the program's name and points to the help of the command in use.
  auto says = [](const dg::test::CliRun& result, const std::string& message, const std::string& help) {
    CAPTURE(result.output);
    CHECK(result.status == 2);
    CHECK(result.output.starts_with("dockgrammar: "));
    CHECK(result.output.find(message) != std::string::npos);
    CHECK(result.output.find("Run '" + help + "'") != std::string::npos);
  };
  says(run("analyze " + model + " -q --seed abc"), "--seed: expected a whole number 0 or more, got 'abc'",
       "dockgrammar analyze --help");
  // strtoull would read -1 as 2^64 - 1, and 2^64 as 2^64 - 1 too.
  says(run("analyze " + model + " -q --seed -1"), "--seed: expected a whole number 0 or more, got '-1'",
       "dockgrammar analyze --help");
  says(run("analyze " + model + " -q --seed 18446744073709551616"), "got '18446744073709551616'", "dockgrammar analyze --help");
  says(run("generate nothing.grammar.json --count x -o out"), "--count: expected a whole number from 1 to 1000000, got 'x'",
       "dockgrammar generate --help");
  says(run("generate nothing.grammar.json --count 2.5 -o out"), "got '2.5'", "dockgrammar generate --help");
  says(run("analyze " + model + " -q --threads 1.5"), "--threads: expected a whole number from 0 to 4096, got '1.5'",
       "dockgrammar analyze --help");
  says(run("generate nothing.grammar.json --max-triangles many -o out"),
       "--max-triangles: expected a whole number from 1 to 1000000000, got 'many'", "dockgrammar generate --help");
  says(run("verify " + model + " " + model + " --samples 2.5"), "--samples: expected a whole number from 1 to 100000000",
       "dockgrammar verify --help");
  says(run("lsystem derive plant.ls -o plant.png --size 8"), "", "dockgrammar lsystem derive --help");
  says(run("analyse " + model), "unknown command 'analyse' (commands: info, analyze,", "dockgrammar --help");
  says(run(""), "no command given (commands: info, analyze,", "dockgrammar --help");
  // The largest seed is a seed.
  const dg::test::CliRun largest = run("analyze " + model + " -q --seed 18446744073709551615 -o " + (folder / "out").string());
  CHECK(largest.status == 0);
  std::filesystem::remove_all(folder);
}

TEST_CASE("options: an output folder that a file stands in the way of is one clear error", "[tools]") {
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-output-folder-test");
  const std::string model = std::string(DOCKGRAMMAR_SOURCE_DIR) + "/assets/models/fence_4.obj";
  const std::filesystem::path file = folder / "taken.obj";
  std::ofstream(file) << "# not a folder\n";
  for (const std::filesystem::path& out : {file, file / "deeper"}) {
    CAPTURE(out);
    const dg::test::CliRun run = dg::test::run_cli("analyze " + model + " -q -o " + out.string(), folder);
    CHECK(run.status == 2);
    CHECK(run.output.find(out.string() + ": cannot create the output folder: " + file.string() + " is a file, not a folder") !=
          std::string::npos);
  }
}
