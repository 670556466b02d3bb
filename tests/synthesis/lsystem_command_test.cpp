// End-to-end runs of `dockgrammar lsystem derive|print`.

#include "support/cli_run.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;

using Run = dg::test::CliRun;

Run run(const std::string& arguments, const fs::path& folder) { return dg::test::run_cli(arguments, folder); }

void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace

TEST_CASE("lsystem derive renders SVG and PNG and reports bad input with exit 2", "[synthesis][cli]") {
  const fs::path folder = dg::test::fresh_folder("dockgrammar-lsystem-cli-test");
  write(folder / "plant.ls", "axiom: F\nangle: 25.7\nheading: 90\nF -> F[+F]F[-F]F\n");
  write(folder / "broken.ls", "axiom: F\nangle: 25.7\nF -> F[+F(]F\n");
  write(folder / "stochastic.ls", "axiom: F\nangle: 30\nF -> (0.5) F[+F]F\nF -> (0.5) F[-F]F\n");

  Run ok = run("lsystem derive " + (folder / "plant.ls").string() + " -n 3 -o " + (folder / "plant.svg").string(), folder);
  CHECK(ok.status == 0);
  CHECK(ok.output.find("125 elements") != std::string::npos);
  CHECK(fs::exists(folder / "plant.svg"));

  ok = run("lsystem derive " + (folder / "plant.ls").string() + " -n 3 --jitter-angle 5 --seed 2 --size 128 -o " +
               (folder / "plant.png").string(),
           folder);
  CHECK(ok.status == 0);
  CHECK(fs::file_size(folder / "plant.png") > 100);

  // Same seed, same bytes; another seed, other bytes.
  const std::string derive_stochastic = "lsystem derive " + (folder / "stochastic.ls").string() + " -n 4 ";
  run(derive_stochastic + "--seed 5 -o " + (folder / "a.svg").string(), folder);
  run(derive_stochastic + "--seed 5 -o " + (folder / "b.svg").string(), folder);
  run(derive_stochastic + "--seed 6 -o " + (folder / "c.svg").string(), folder);
  auto read = [](const fs::path& p) {
    std::ifstream in(p);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  CHECK(read(folder / "a.svg") == read(folder / "b.svg"));
  CHECK(read(folder / "a.svg") != read(folder / "c.svg"));

  Run bad = run("lsystem derive " + (folder / "broken.ls").string() + " -o " + (folder / "x.svg").string(), folder);
  CHECK(bad.status == 2);
  CHECK(bad.output.find("broken.ls:3: column 10:") != std::string::npos);
  CHECK_FALSE(fs::exists(folder / "x.svg"));

  Run limit = run("lsystem derive " + (folder / "plant.ls").string() + " -n 12 --max-modules 10000 -o " +
                      (folder / "y.png").string(),
                  folder);
  CHECK(limit.status == 2);
  CHECK(limit.output.find("derivation exceeds 10000 modules") != std::string::npos);
  CHECK_FALSE(fs::exists(folder / "y.png"));

  Run extension = run("lsystem derive " + (folder / "plant.ls").string() + " -o " + (folder / "z.txt").string(), folder);
  CHECK(extension.status == 2);
  Run replace = run("lsystem derive " + (folder / "plant.ls").string() + " --replace Q=F -o " + (folder / "z.svg").string(),
                    folder);
  CHECK(replace.status == 2);
  CHECK(replace.output.find("Q occurs in neither") != std::string::npos);

  // --replace takes one value per use, so the FILE after it stays the input.
  Run replaced = run("lsystem derive --replace F=G " + (folder / "plant.ls").string() + " -n 2 -o " +
                         (folder / "g.svg").string(),
                     folder);
  CHECK(replaced.status == 0);
  CHECK(replaced.output.find("0 elements") != std::string::npos);

  Run print = run("lsystem print --json " + (folder / "plant.ls").string(), folder);
  CHECK(print.status == 0);
  CHECK(print.output.find("\"F\": \"F[+F]F[-F]F\"") != std::string::npos);
  fs::remove_all(folder);
}
