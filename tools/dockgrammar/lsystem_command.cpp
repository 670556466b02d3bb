// `dockgrammar lsystem derive|print`: re-derive an L-system and render it, with the editing
// operations of Št'ava et al. 2010 §6 (more iterations, randomization, symbol replacement).

#include "tools/dockgrammar/commands.h"
#include "tools/dockgrammar/number_checks.h"

#include "geometry/errors.h"
#include "geometry/model_io.h"
#include "geometry/image.h"
#include "grammar/derivation.h"
#include "grammar/grammar_length.h"
#include "grammar/lsystem_json.h"
#include "grammar/lsystem_text.h"
#include "grammar/symbol_replacement.h"
#include "synthesis/render.h"
#include "synthesis/turtle.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace dg::cli {

namespace {

struct DeriveOptions {
  std::string input;
  std::string output;
  std::optional<int> iterations;
  std::uint64_t seed = 1;
  double jitter_angle = 0;
  double jitter_scale = 0;
  std::vector<std::string> replacements;
  std::size_t max_modules = DerivationLimits{}.max_modules;
  int size = 512;
  double line_width = 1.5;
  bool json = false;
};

struct PrintOptions {
  std::string input;
  bool json = false;
};

LSystem read_lsystem(const std::string& path) {
  return lower_extension(path) == ".json" ? read_lsystem_json(path) : read_lsystem_text(path);
}

void apply_replacements(LSystem& system, const std::vector<std::string>& replacements) {
  for (const std::string& replacement : replacements) {
    const std::size_t equals = replacement.find('=');
    const std::string from = replacement.substr(0, equals);
    const std::string to = equals == std::string::npos ? "" : replacement.substr(equals + 1);
    if (!is_symbol_name(from) || !is_symbol_name(to))
      throw InputError("--replace " + replacement + ": expected SYMBOL=SYMBOL, like P2=A");
    if (replace_symbol(system, from, to) == 0)
      throw InputError("--replace " + replacement + ": " + from + " occurs in neither the axiom nor any successor");
  }
}

void run_derive(const DeriveOptions& options) {
  const std::string extension = lower_extension(options.output);
  if (extension != ".svg" && extension != ".png")
    throw InputError(options.output + ": the output must end in .svg or .png");
  std::error_code ignored;
  if (std::filesystem::equivalent(options.input, options.output, ignored))
    throw InputError(options.output + ": refusing to overwrite the input");
  LSystem system = read_lsystem(options.input);
  apply_replacements(system, options.replacements);

  DerivationOptions derivation_options;
  derivation_options.steps = options.iterations;
  derivation_options.seed = options.seed;
  derivation_options.limits.max_modules = options.max_modules;
  Derivation derivation;
  try {
    derivation = derive(system, derivation_options);
  } catch (const InputError& error) {
    throw InputError(options.input + ": " + error.what());
  }

  TurtleOptions turtle;
  try {
    turtle = turtle_options(system.turtle);
  } catch (const InputError& error) {
    throw InputError(options.input + ": " + error.what());
  }
  turtle.jitter_angle_deg = options.jitter_angle;
  turtle.jitter_scale = options.jitter_scale;
  turtle.seed = options.seed;
  Drawing drawing;
  try {
    drawing = interpret(derivation.modules, turtle);
  } catch (const InputError& error) {
    throw InputError(options.input + ": " + error.what());
  }

  RenderOptions render;
  render.long_side_px = options.size;
  render.line_width_px = options.line_width;
  if (extension == ".svg")
    write_svg(options.output, drawing, render);
  else
    write_png(options.output, rasterize(drawing, render));

  if (options.json) {
    const nlohmann::ordered_json report = {{"input", options.input},
                                           {"output", options.output},
                                           {"steps", derivation.steps},
                                           {"modules", derivation.modules.size()},
                                           {"elements", drawing.strokes.size()},
                                           {"seed", options.seed}};
    fmt::print("{}\n", report.dump());
  } else {
    fmt::print("{}: {} steps, {} modules, {} elements -> {}\n", options.input, derivation.steps,
               derivation.modules.size(), drawing.strokes.size(), options.output);
  }
}

void run_print(const PrintOptions& options) {
  const LSystem system = read_lsystem(options.input);
  if (options.json) {
    nlohmann::ordered_json json = lsystem_to_json(system);
    json["grammar_length"] = grammar_length(system);
    fmt::print("{}\n", json.dump(2));
  } else {
    fmt::print("{}", format_lsystem_text(system));
  }
}

}  // namespace

void add_lsystem_command(CLI::App& app) {
  CLI::App* lsystem = app.add_subcommand("lsystem", "2D L-systems: re-derive and render them, convert between forms");
  lsystem->require_subcommand(1);

  auto derive_options = std::make_shared<DeriveOptions>();
  CLI::App* derive_command = lsystem->add_subcommand(
      "derive",
      "Derive an L-system (text .ls or JSON .json, see docs/lsystem-syntax.md) and draw it with the turtle.\n"
      "Example: dockgrammar lsystem derive tree.ls -n 6 --jitter-angle 5 --seed 3 -o tree.png");
  derive_command->add_option("FILE", derive_options->input, "L-system file: text form, or JSON (also a corpus case .json)")
      ->required()
      ->check(CLI::ExistingFile);
  derive_command->add_option("-o,--output", derive_options->output, "picture to write: OUT.svg or OUT.png")->required();
  derive_command->add_option("-n,--iterations", derive_options->iterations,
                             "derivation steps (default: the file's 'iterations', else rewrite until nothing applies)")
      ->check(number_in(0, 1000000));
  derive_command->add_option("--seed", derive_options->seed,
                             "seed for stochastic rules and jitter; the same seed gives the same picture")
      ->capture_default_str()->check(seed_number());
  derive_command->add_option("--jitter-angle", derive_options->jitter_angle,
                             "randomize every turn by up to +-DEG degrees")
      ->check(number_in(0.0, 180.0));
  derive_command->add_option("--jitter-scale", derive_options->jitter_scale,
                             "randomize every length, scale factor and motif size by up to +-F (0.1 = 10%)")
      ->check(number_in(0.0, 0.99));
  derive_command->add_option("--replace", derive_options->replacements,
                             "replace symbol A by B in the axiom and all successors, e.g. P2=A (repeat the option for more)")
      ->allow_extra_args(false);
  derive_command->add_option("--max-modules", derive_options->max_modules,
                             "stop with an error when the derived string grows beyond N modules")
      ->capture_default_str()
      ->check(number_in(std::size_t{1}, std::size_t{1} << 40));
  derive_command->add_option("--size", derive_options->size, "PNG: pixels along the longer side")
      ->capture_default_str()
      ->check(number_in(16, 16384));
  derive_command->add_option("--line-width", derive_options->line_width, "line width in PNG pixels")
      ->capture_default_str()
      ->check(number_in(0.1, 100.0));
  derive_command->add_flag("--json", derive_options->json, "print a machine-readable summary on stdout");
  derive_command->callback([derive_options] { run_derive(*derive_options); });

  auto print_options = std::make_shared<PrintOptions>();
  CLI::App* print_command =
      lsystem->add_subcommand("print", "Read an L-system file and print it in the text form, or with --json in the JSON form");
  print_command->add_option("FILE", print_options->input, "L-system file: text form, or JSON")
      ->required()
      ->check(CLI::ExistingFile);
  print_command->add_flag("--json", print_options->json, "print the JSON form (with grammar_length)");
  print_command->callback([print_options] { run_print(*print_options); });
  add_lsystem_infer_subcommand(*lsystem);
}

}  // namespace dg::cli
