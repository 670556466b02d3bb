// dockgrammar-assets: writes the parametric exemplar models with their ground truth.
//
//   dockgrammar-assets NAME [--param key=value ...] [--detail K] [--target-triangles N] -o OUT.obj
//   dockgrammar-assets NAME [--param key=value ...] --points N [--seed S] [--noise SIGMA] -o OUT.ply
//   dockgrammar-assets --list
//   dockgrammar-assets --all -o DIR
//
// Errors print one line on stderr; exit status 2 for bad usage/input, 1 for internal failures.

#include "assets/generator/asset.h"
#include "assets/generator/committed_instances.h"
#include "geometry/errors.h"
#include "geometry/model_io.h"
#include "tools/dockgrammar/number_checks.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <iostream>

namespace {

/// Parses "key=value" options into a JSON object; numeric values become JSON numbers.
nlohmann::json parse_params(const std::vector<std::string>& items) {
  nlohmann::json params = nlohmann::json::object();
  for (const std::string& item : items) {
    const std::size_t equals = item.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw dg::InputError(fmt::format("--param '{}': expected key=value", item));
    }
    const std::string key = item.substr(0, equals), text = item.substr(equals + 1);
    const nlohmann::json value = nlohmann::json::parse(text, nullptr, false);
    params[key] = !value.is_discarded() && value.is_number() ? value : nlohmann::json(text);
  }
  return params;
}

/// Runs the command; returns the exit status.
int run(int argc, char** argv) {
  CLI::App app{"Writes parametric exemplar models (OBJ/PLY/GLB) with their ground truth (JSON)"};
  std::string name;
  std::vector<std::string> param_items;
  int detail = 0;
  std::size_t target = 0;
  std::filesystem::path output;
  bool list = false, all = false;
  std::size_t points = 0;
  std::uint64_t seed = 1;
  double noise = 0.0;
  app.add_option("name", name, "model name (see --list)");
  app.add_option("--param", param_items, "model parameter key=value (repeatable)");
  app.add_option("--detail", detail, "tessellation detail K >= 1 (triangles grow with K^2)")->check(dg::cli::number_in(1, 1000));
  app.add_option("--target-triangles", target, "choose the detail that comes closest to N triangles")->check(dg::cli::number_in(std::size_t{1}, std::numeric_limits<std::size_t>::max()));
  app.add_option("-o,--output", output, "output mesh file (NAME) or folder (--all)");
  app.add_option("--points", points, "write a point cloud of N points drawn on the surface (PLY) instead of the mesh")
      ->check(dg::cli::number_in(std::size_t{1}, std::size_t{100'000'000}));
  app.add_option("--seed", seed, "seed of the drawn points (with --points)")->capture_default_str()->check(dg::cli::seed_number());
  app.add_option("--noise", noise, "with --points: Gaussian noise of this standard deviation per axis, model units")
      ->check(dg::cli::number_in(0.0, 1e6));
  app.add_flag("--list", list, "print the model names");
  app.add_flag("--all", all, "write the committed small instances into the folder given by -o");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "dockgrammar-assets: " << e.what() << "\n";
    return 2;
  }

  if (list) {
    for (const std::string& known : dg::assets::asset_names()) std::cout << known << "\n";
    return 0;
  }
  if (output.empty()) throw dg::InputError("missing -o (output file, or folder with --all)");
  if (all) {
    if (!name.empty() || !param_items.empty() || detail != 0 || target != 0 || points != 0) {
      throw dg::InputError("--all takes only -o DIR");
    }
    std::error_code error;
    std::filesystem::create_directories(output, error);
    if (error) throw dg::InputError(fmt::format("{}: cannot create folder ({})", output.string(), error.message()));
    for (const dg::assets::Instance& instance : dg::assets::committed_instances()) {
      const dg::assets::Asset asset = dg::assets::make_asset(instance.model, instance.params);
      dg::assets::write_asset_files(asset, output / (instance.stem + ".obj"));
      std::cout << fmt::format("{}: {} triangles\n", instance.stem, asset.mesh.triangles.size());
    }
    return 0;
  }
  if (name.empty()) throw dg::InputError("missing model NAME (see --list)");
  if (detail != 0 && target != 0) throw dg::InputError("--detail and --target-triangles exclude each other");
  if (noise > 0.0 && points == 0) throw dg::InputError("--noise needs --points");
  nlohmann::json params = parse_params(param_items);
  if (detail != 0) params["detail"] = detail;
  const dg::assets::Asset asset = target == 0 ? dg::assets::make_asset(name, params) : dg::assets::make_asset_with_triangles(name, params, target);
  if (points != 0) {
    dg::assets::write_asset_points(asset, output, points, seed, noise);
    std::cout << fmt::format("{}: {} points drawn on {} triangles -> {} and {}\n", asset.name, points, asset.mesh.triangles.size(),
                             output.string(), dg::assets::ground_truth_path(output).string());
    std::cout << fmt::format("z is up: dockgrammar analyze {} --up z\n", output.string());
    return 0;
  }
  dg::assets::write_asset_files(asset, output);
  std::cout << fmt::format("{}: {} triangles -> {} and {}\n", asset.name, asset.mesh.triangles.size(), output.string(),
                           dg::assets::ground_truth_path(output).string());
  if (dg::lower_extension(output) == ".glb")
    std::cout << fmt::format("turned to glTF's y-up (the JSON keeps the generator's z-up values): dockgrammar analyze {}\n",
                             output.string());
  else
    std::cout << fmt::format("z is up (most OBJ readers assume y): dockgrammar analyze {} --up z\n", output.string());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const dg::InputError& e) {
    std::cerr << "dockgrammar-assets: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "dockgrammar-assets: internal error: " << e.what() << "\n";
    return 1;
  }
}
