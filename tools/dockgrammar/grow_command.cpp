// `dockgrammar grow SCENE.json -o OUT.svg|OUT.png`: guided growth of Open L-systems inside
// linked guides (Beneš et al. 2011), with optional incremental regrowth after guide edits.

#include "tools/dockgrammar/commands.h"
#include "tools/dockgrammar/number_checks.h"

#include "geometry/errors.h"
#include "geometry/model_io.h"
#include "geometry/stopwatch.h"
#include "synthesis/growth.h"
#include "synthesis/growth_render.h"
#include "synthesis/guide_edit.h"
#include "synthesis/render.h"
#include "synthesis/scene_file.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace dg::cli {

namespace {

struct GrowOptions {
  std::string scene;
  std::string output;
  std::string edits;
  std::uint64_t seed = 1;
  int size = 1024;
  double line_width = 1.2;
  bool json = false;
};

// Applies edits and returns the guides they changed (sorted, without repeats).
std::vector<std::size_t> apply_edits(GrowthScene& scene, const std::vector<GuideEdit>& edits) {
  std::vector<std::size_t> changed;
  for (const GuideEdit& edit : edits) {
    const std::vector<std::size_t> moved = apply_guide_edit(scene, edit);
    changed.insert(changed.end(), moved.begin(), moved.end());
  }
  std::sort(changed.begin(), changed.end());
  changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
  return changed;
}

void run_grow(const GrowOptions& options) {
  const std::string extension = lower_extension(options.output);
  if (extension != ".svg" && extension != ".png")
    throw InputError(options.output + ": the output must end in .svg or .png");
  GrowthScene scene = read_growth_scene(options.scene);
  try {
    apply_edits(scene, scene.edits);
    check_growth_scene(scene);
  } catch (const InputError& error) {
    throw InputError(options.scene + ": " + error.what());
  }
  GrowthOptions growth_options;
  growth_options.seed = options.seed;

  Stopwatch clock;
  GrowthResult result;
  try {
    result = grow(scene, growth_options);
  } catch (const InputError& error) {
    throw InputError(options.scene + ": " + error.what());
  } catch (const LimitError& error) {
    throw LimitError(options.scene + ": " + error.what());
  }
  const double grow_s = clock.lap();
  const std::size_t grown_elements = result.elements();
  const int grown_steps = result.steps;
  double regrow_s = 0;
  if (!options.edits.empty()) {
    const std::vector<GuideEdit> edits = read_guide_edits(options.edits, scene);
    std::vector<std::size_t> changed;
    try {
      changed = apply_edits(scene, edits);
      check_growth_scene(scene);
    } catch (const InputError& error) {
      throw InputError(options.edits + ": " + error.what());
    }
    Stopwatch again;
    try {
      result = regrow(scene, result, changed, growth_options);
    } catch (const InputError& error) {
      throw InputError(options.edits + ": " + error.what());
    } catch (const LimitError& error) {
      throw LimitError(options.edits + ": " + error.what());
    }
    regrow_s = again.lap();
  }

  RenderOptions render;
  render.long_side_px = options.size;
  render.line_width_px = options.line_width;
  Drawing drawing = growth_drawing(scene, result);
  if (extension == ".svg") {
    // Scene units are often small (a palm 2 units tall): scale so the page is --size wide in SVG
    // units too, as viewers take width and height as pixels.
    const PageFrame frame = page_frame(drawing, render.margin_fraction);
    const double factor = options.size / std::max(frame.width, frame.height);
    for (Stroke& stroke : drawing.strokes)
      stroke.path = map_path(stroke.path, [&](const Vec2& p) { return Vec2(p * factor); });
    write_svg(options.output, drawing, render);
  } else {
    write_png(options.output, rasterize(drawing, render));
  }

  int tokens_used = 0;
  for (const TokenState& token : result.tokens) tokens_used += token.used;
  if (options.json) {
    nlohmann::ordered_json guides = nlohmann::ordered_json::array();
    for (std::size_t g = 0; g < scene.guides.size(); ++g)
      guides.push_back({{"id", scene.guides[g].name},
                        {"elements", result.guides[g].segments.size() + result.guides[g].motifs.size()},
                        {"seeds", result.guides[g].seeds}});
    nlohmann::ordered_json links = nlohmann::ordered_json::array();
    for (const TokenState& token : result.tokens) links.push_back({{"free", token.free}, {"used", token.used}});
    nlohmann::ordered_json report = {{"scene", options.scene},     {"output", options.output},
                                     {"seed", options.seed},       {"steps", result.steps},
                                     {"elements", result.elements()}, {"tokens_used", tokens_used},
                                     {"guides", guides},           {"links", links},
                                     {"grow_seconds", grow_s}};
    if (!options.edits.empty()) {
      report["regrown_guides"] = result.regrown_guides;
      report["regrow_seconds"] = regrow_s;
    }
    fmt::print("{}\n", report.dump());
  } else {
    if (options.edits.empty()) {
      fmt::print("{}: {} guides, {} elements, {} tokens used, {} steps, {:.3f} s -> {}\n", options.scene,
                 scene.guides.size(), grown_elements, tokens_used, grown_steps, grow_s, options.output);
    } else {
      fmt::print("{}: {} guides, {} elements, {} steps, {:.3f} s\n", options.scene, scene.guides.size(), grown_elements,
                 grown_steps, grow_s);
      fmt::print("{}: regrew {} of {} guides in {:.3f} s: {} elements, {} tokens used -> {}\n", options.edits,
                 result.regrown_guides, scene.guides.size(), regrow_s, result.elements(), tokens_used, options.output);
    }
  }
}

}  // namespace

void add_grow_command(CLI::App& app) {
  auto options = std::make_shared<GrowOptions>();
  CLI::App* grow_command = app.add_subcommand(
      "grow",
      "Grow Open L-systems inside linked guides (guided procedural modeling, see docs/scene-file.md).\n"
      "Example: dockgrammar grow assets/scenes/palm.json -o palm.png");
  grow_command->add_option("SCENE", options->scene, "scene file (JSON)")->required()->check(CLI::ExistingFile);
  grow_command->add_option("-o,--output", options->output, "picture to write: OUT.svg or OUT.png")->required();
  grow_command->add_option("--seed", options->seed, "seed of stochastic rules; the same seed gives the same picture")
      ->capture_default_str()->check(seed_number());
  grow_command->add_option("--edit", options->edits,
                           "edits (JSON) applied after growing; only the changed guides and their dependents regrow")
      ->check(CLI::ExistingFile);
  grow_command->add_option("--size", options->size, "pixels along the longer side (SVG: its width or height)")
      ->capture_default_str()
      ->check(number_in(16, 16384));
  grow_command->add_option("--line-width", options->line_width, "line width in PNG pixels")
      ->capture_default_str()
      ->check(number_in(0.1, 100.0));
  grow_command->add_flag("--json", options->json,
                         "print element counts per guide, tokens used and times as JSON on stdout");
  grow_command->callback([options] { run_grow(*options); });
}

}  // namespace dg::cli
