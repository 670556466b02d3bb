// dockgrammar-bench: times the foundation stages (clean, feature lines, voxel surface) and
// OpenVDB's meshToLevelSet on generated models of growing size and on the largest corpus
// models, with 1 and 2 threads, each run in its own child process so its peak memory is its own.
// Appends a table to bench/results.md (or --output) with the date, machine and commit.

#include "assets/generator/asset.h"
#include "bench/openvdb_reference.h"
#include "geometry/model_io.h"
#include "geometry/prepared_model.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <thread>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace {

using Json = nlohmann::json;

// Runs `work` in a forked child and returns its JSON result with "peak_rss_mb" added.
// The parent never starts TBB, so forking is safe.
Json run_isolated(const std::function<Json()>& work) {
  int channel[2];
  if (::pipe(channel) != 0) throw std::runtime_error("pipe failed");
  const pid_t child = ::fork();
  if (child < 0) throw std::runtime_error("fork failed");
  if (child == 0) {
    ::close(channel[0]);
    std::string text;
    try {
      text = work().dump();
    } catch (const std::exception& e) {
      text = Json{{"error", e.what()}}.dump();
    }
    std::size_t written = 0;
    while (written < text.size()) {
      const ssize_t n = ::write(channel[1], text.data() + written, text.size() - written);
      if (n <= 0) break;
      written += static_cast<std::size_t>(n);
    }
    ::close(channel[1]);
    ::_exit(0);
  }
  ::close(channel[1]);
  std::string text;
  char buffer[4096];
  ssize_t n;
  while ((n = ::read(channel[0], buffer, sizeof buffer)) > 0) text.append(buffer, static_cast<std::size_t>(n));
  ::close(channel[0]);
  int status = 0;
  rusage usage{};
  ::wait4(child, &status, 0, &usage);
  Json result = text.empty() ? Json{{"error", "child process died"}} : Json::parse(text);
  result["peak_rss_mb"] = static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB
  return result;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Case {
  std::string name;
  std::function<dg::Model()> load;  // runs inside the child
  bool from_file = false;
};

std::string shell_line(const char* command) {
  std::string out;
  if (FILE* pipe = ::popen(command, "r")) {
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
    ::pclose(pipe);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  return out;
}

std::string machine_description() {
  const std::string cpu = shell_line("grep -m1 'model name' /proc/cpuinfo | cut -d: -f2");
  const std::string memory = shell_line("awk '/MemTotal/ {printf \"%.0f GB\", $2/1048576}' /proc/meminfo");
  return fmt::format("{} x {}, {}", std::thread::hardware_concurrency(), cpu.empty() ? "unknown CPU" : cpu.substr(1), memory);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"dockgrammar-bench: time the voxel surface stages against OpenVDB's meshToLevelSet"};
  std::vector<std::size_t> sizes{10'000, 100'000, 500'000, 1'000'000};
  std::vector<int> threads{1, 2};
  std::string corpus = std::string(DOCKGRAMMAR_SOURCE_DIR) + "/../shared/corpus/meshes";
  std::string output = std::string(DOCKGRAMMAR_SOURCE_DIR) + "/bench/results.md";
  std::string asset = "facade";
  app.add_option("--sizes", sizes, "Target triangle counts of the generated models")->delimiter(',');
  app.add_option("--threads", threads, "Thread counts to run with")->delimiter(',');
  app.add_option("--asset", asset, "Generated model family (see dockgrammar-assets --list)");
  app.add_option("--corpus", corpus, "Corpus folder; its largest models are timed too (skipped when absent)");
  app.add_option("-o,--output", output, "Markdown file the results are appended to");
  CLI11_PARSE(app, argc, argv);

  std::vector<Case> cases;
  for (std::size_t target : sizes)
    cases.push_back({fmt::format("{} ~{}k", asset, target / 1000), [asset, target] {
                       dg::Model model;
                       model.mesh = dg::assets::make_asset_with_triangles(asset, nlohmann::json::object(), target).mesh;
                       return model;
                     }});
  for (const char* relative : {"organic-stanford-bunny/stanford-bunny.obj", "messy-map-zdm2/zdm2.obj",
                               "large-scopia-chandelier/chandelier-lamp.obj"}) {
    const std::filesystem::path path = std::filesystem::path(corpus) / relative;
    if (!std::filesystem::exists(path)) {
      fmt::print(stderr, "skipping {}: not found\n", path.string());
      continue;
    }
    cases.push_back({path.filename().string(), [path] { return dg::read_model(path); }, true});
  }

  std::string rows;
  for (const Case& c : cases) {
    for (int t : threads) {
      fmt::print(stderr, "{} with {} thread(s)...\n", c.name, t);
      const Json ours = run_isolated([&] {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(t));
        auto start = std::chrono::steady_clock::now();
        dg::Model model = c.load();
        const double load = seconds_since(start);
        const std::size_t triangles = model.mesh.triangles.size();
        const dg::PreparedModel prepared = dg::prepare_model(std::move(model));
        Json stages = Json::object();
        for (const auto& timing : prepared.timings) stages[timing.stage] = timing.seconds;
        return Json{{"triangles", triangles},
                    {"load", load},
                    {"stages", stages},
                    {"voxels", prepared.surface.cell_count()},
                    {"eps", prepared.surface.eps()}};
      });
      if (ours.contains("error")) {
        fmt::print(stderr, "  failed: {}\n", ours["error"].get<std::string>());
        continue;
      }
      const double eps = ours["eps"].get<double>();
      const Json reference = run_isolated([&] {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(t));
        const dg::Model model = c.load();
        const auto start = std::chrono::steady_clock::now();
        const std::size_t voxels = dg::bench::openvdb_mesh_to_level_set(model.mesh, eps);
        return Json{{"seconds", seconds_since(start)}, {"voxels", voxels}};
      });
      const Json& stages = ours["stages"];
      const double voxel_seconds = stages.value("voxel surface", 0.0);
      const double reference_seconds = reference.value("seconds", 0.0);
      rows += fmt::format("| {} | {} | {} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {} | {:.0f} | {:.3f} | {:.0f} | {:.2f} |\n",
                          c.name, ours["triangles"].get<std::size_t>(), t, c.from_file ? ours["load"].get<double>() : 0.0,
                          stages.value("clean", 0.0), stages.value("feature lines", 0.0), voxel_seconds,
                          ours["voxels"].get<std::size_t>(), ours["peak_rss_mb"].get<double>(), reference_seconds,
                          reference.value("peak_rss_mb", 0.0),
                          reference_seconds > 0.0 ? voxel_seconds / reference_seconds : 0.0);
      fmt::print(stderr, "  voxel surface {:.3f} s, meshToLevelSet {:.3f} s\n", voxel_seconds, reference_seconds);
    }
  }

  const std::string commit = shell_line(("git -C " + std::string(DOCKGRAMMAR_SOURCE_DIR) +
                                         " describe --always --dirty 2>/dev/null").c_str());
  const std::string date = shell_line("date -u '+%Y-%m-%d %H:%M UTC'");
  std::ostringstream section;
  section << fmt::format("\n## Foundation stages, {} (commit {})\n\nMachine: {}. Build: {}.\n\n", date,
                         commit.empty() ? "unknown" : commit, machine_description(), DOCKGRAMMAR_BUILD_TYPE);
  section << "| model | triangles | threads | load s | clean s | feature lines s | voxel surface s | voxels | "
             "peak MB | meshToLevelSet s | its peak MB | ratio ours/OpenVDB |\n";
  section << "|---|---|---|---|---|---|---|---|---|---|---|---|\n" << rows;
  std::ofstream out(output, std::ios::app);
  out << section.str();
  fmt::print("{}", section.str());
  return out ? 0 : 1;
}
