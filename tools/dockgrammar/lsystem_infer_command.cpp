// `dockgrammar lsystem infer INPUT.svg|INPUT.png`: infer an L-system from a vector drawing or a
// pixel image (Št'ava et al. 2010, Guo et al. 2020), print it and write it.

#include "tools/dockgrammar/commands.h"
#include "tools/dockgrammar/number_checks.h"

#include "geometry/atomic_file.h"
#include "geometry/errors.h"
#include "geometry/model_io.h"
#include "geometry/png_reader.h"
#include "geometry/svg_reader.h"
#include "grammar/generalization.h"
#include "grammar/grammar_length.h"
#include "grammar/inference_drawing.h"
#include "grammar/inference_pixels.h"
#include "grammar/lsystem_json.h"
#include "grammar/lsystem_text.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace dg::cli {

namespace {

struct InferOptions {
  std::string input;
  std::string output;
  bool json = false;
  std::optional<double> generalize_w0;
  DrawingInferenceOptions inference;
};

void run_infer(const InferOptions& options) {
  const std::string input_extension = lower_extension(options.input);
  if (input_extension != ".svg" && input_extension != ".png")
    throw InputError(options.input + ": lsystem infer reads .svg (vector) or .png (pixel) files");
  if (!options.output.empty()) {
    const std::string extension = lower_extension(options.output);
    if (extension != ".ls" && extension != ".json") throw InputError(options.output + ": the output must end in .ls or .json");
    std::error_code ignored;
    if (std::filesystem::equivalent(options.input, options.output, ignored))
      throw InputError(options.output + ": refusing to overwrite the input");
  }
  InferredLSystem inferred;
  std::optional<PixelFrontEnd> front_end;
  if (input_extension == ".svg") {
    const SvgDrawing drawing = read_svg(options.input);
    try {
      inferred = infer_drawing_lsystem(drawing, options.inference);
    } catch (const InputError& error) {
      throw InputError(options.input + ": " + error.what());
    }
  } else {
    const Image image = read_png(options.input);
    PixelInferenceOptions pixel;
    pixel.drawing = options.inference;
    try {
      PixelInference result = infer_pixel_lsystem(image, pixel);
      inferred = std::move(result.inferred);
      front_end = result.front_end;
    } catch (const InputError& error) {
      throw InputError(options.input + ": " + error.what());
    }
  }
  std::vector<RuleMerge> merges;
  if (options.generalize_w0) {
    GeneralizationOptions generalization;
    generalization.w0 = *options.generalize_w0;
    Generalization general = generalize(inferred.lsystem, generalization);
    merges = general.merges;
    inferred.lsystem = std::move(general.system);
    inferred.text = "# " + inferred.method + " inference, generalized with w0 = " + fmt::format("{}", generalization.w0) + ": " +
                    std::to_string(merges.size()) + " merges\n" + format_lsystem_text(inferred.lsystem);
  }
  nlohmann::ordered_json json = lsystem_to_json(inferred.lsystem);
  json["grammar_length"] = grammar_length(inferred.lsystem);
  json["start_svg"] = {inferred.start_svg.x(), inferred.start_svg.y()};
  json["elements"] = inferred.elements;
  json["terminals"] = inferred.terminals;
  json["method"] = inferred.method;
  json["comparison"] = inferred.comparison;
  if (options.generalize_w0) {
    json["merges"] = nlohmann::ordered_json::array();
    for (const RuleMerge& m : merges)
      json["merges"].push_back({{"kept", m.kept}, {"merged", m.merged}, {"edit_distance", m.edit_distance}, {"cost", m.cost}});
  }
  json["timings_s"] = {{"instancing", inferred.timings.instancing_s},
                       {"rules", inferred.timings.rules_s},
                       {"total", inferred.timings.total_s}};
  if (front_end)
    json["pixels"] = {{"ink", front_end->ink_pixels},         {"skeleton", front_end->skeleton_pixels},
                      {"nodes", front_end->nodes},            {"chains", front_end->chains},
                      {"pieces", front_end->pieces},          {"components", front_end->components},
                      {"front_end_s", front_end->seconds}};
  if (!options.output.empty()) {
    const bool as_json = lower_extension(options.output) == ".json";
    write_file_atomically(options.output, [&](std::ostream& out) { out << (as_json ? json.dump(2) + "\n" : inferred.text); }, false);
  }
  if (options.json) fmt::print("{}\n", json.dump(2));
  else fmt::print("{}", inferred.text);
}

}  // namespace

void add_lsystem_infer_subcommand(CLI::App& lsystem) {
  auto options = std::make_shared<InferOptions>();
  CLI::App* command = lsystem.add_subcommand(
      "infer",
      "Infer an L-system from a vector drawing (each SVG element one atomic element; Št'ava et al. 2010 and Guo et al. 2020)\n"
      "or from a PNG image of dark strokes on a light background (skeleton, stroke graph, then the same inference).\n"
      "Example: dockgrammar lsystem infer helix.svg -o helix.ls && dockgrammar lsystem derive helix.ls -o helix.png");
  command->add_option("INPUT", options->input, "vector drawing (.svg) or image (.png)")->required()->check(CLI::ExistingFile);
  command->add_option("-o,--output", options->output, "write the L-system here: OUT.ls (text form) or OUT.json");
  command->add_flag("--json", options->json, "print the JSON form with grammar_length, start_svg and timings_s");
  ImportanceWeights& w = options->inference.vector.clusters.weights;
  command->add_option("--w-n", w.w_n, "importance weight of the number of absorbed elements")->capture_default_str()->check(number_in(0.0, 1.0));
  command->add_option("--w-h", w.w_h, "importance weight of proximity (merge neighbours first)")->capture_default_str()->check(number_in(0.0, 1.0));
  command->add_option("--w-phi", w.w_phi, "importance weight of element similarity")->capture_default_str()->check(number_in(0.0, 1.0));
  command->add_option("--w-l", w.w_l, "importance weight of sequence length")->capture_default_str()->check(number_in(0.0, 1.0));
  command->add_option("--generalize", options->generalize_w0,
                      "merge similar rules into stochastic ones (Guo et al. 2020 §4.3) with weight W0 in [0, 1] of the length change "
                      "against the edit distance")
      ->check(number_in(0.0, 1.0));
  command->add_option("--similarity", options->inference.vector.similarity.threshold, "element similarity threshold")
      ->capture_default_str()
      ->check(number_in(0.0, 1.0));
  command->callback([options] { run_infer(*options); });
}

}  // namespace dg::cli
