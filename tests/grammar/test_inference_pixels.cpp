// The instance-tree path (Guo et al. 2020) on the 2D corpus, vector (SVG) and pixel (PNG) input
// side by side: re-derived drawing vs the input strokes (symmetric Hausdorff in % of the SVG
// bounding-box diagonal; PNG results are scaled back by png.px_per_unit), grammar length vs the
// ground truth, angle and scale errors. Targets are asserted on the cases listed as meeting
// them; docs/lsystem-inference.md lists every case's figures, misses included.

#include "tests/grammar/inference_measure.h"

#include "geometry/errors.h"
#include "geometry/png_reader.h"
#include "grammar/grammar_length.h"
#include "grammar/inference_drawing.h"
#include "grammar/inference_pixels.h"
#include "grammar/lsystem_text.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

namespace {

namespace fs = std::filesystem;
using dg::Vec2;

struct Figures {
  bool inferred = false;
  std::string failure;
  std::string method;
  double hausdorff_percent = -1;
  std::size_t length = 0, gt_length = 0;
  double angle_error = -1, scale_error = -1;  // -1: not applicable
  double seconds = 0;
  std::string text;
};

void compare(const dg::InferredLSystem& inferred, const std::string& id, double px_per_unit, Figures& f) {
  const fs::path dir = dg::test::lsystem_corpus_dir();
  const dg::SvgDrawing drawing = dg::read_svg(dir / (id + ".svg"));
  const nlohmann::json truth = nlohmann::json::parse(dg::read_text_file(dir / (id + ".json")));
  f.inferred = true;
  f.method = inferred.method;
  f.text = inferred.text;
  f.seconds = inferred.timings.total_s;
  const double diagonal = dg::test::diagonal_of(dg::test::drawing_points(drawing, 1.0));
  const double spacing = diagonal / 2000;
  const std::vector<Vec2> input = dg::test::drawing_points(drawing, spacing);
  const std::vector<Vec2> output = dg::test::rederived_points(inferred, spacing, px_per_unit);
  f.hausdorff_percent = 100 * dg::test::symmetric_hausdorff(input, output, diagonal / 100) / diagonal;
  f.length = dg::grammar_length(inferred.lsystem);
  f.gt_length = truth["grammar_length"].get<std::size_t>();
  const auto& gt = truth["lsystem"];
  if (gt["angle"].is_number() && inferred.lsystem.turtle.angle_deg) {
    const double a = std::fmod(std::abs(*inferred.lsystem.turtle.angle_deg - gt["angle"].get<double>()), 360.0);
    f.angle_error = std::min(a, 360 - a);
  }
  if (gt["scale"].is_number()) {
    const double r_gt = 1 / gt["scale"].get<double>();
    double r = 1;
    if (inferred.lsystem.turtle.scale) r = 1 / std::min(*inferred.lsystem.turtle.scale, 1 / *inferred.lsystem.turtle.scale);
    f.scale_error = std::abs(r - r_gt) / r_gt;
  }
}

Figures measure_svg(const std::string& id) {
  Figures f;
  const dg::InferredLSystem inferred = dg::infer_drawing_lsystem(dg::read_svg(dg::test::lsystem_corpus_dir() / (id + ".svg")));
  compare(inferred, id, 1, f);
  return f;
}

Figures measure_png(const std::string& id) {
  Figures f;
  const fs::path dir = dg::test::lsystem_corpus_dir();
  const nlohmann::json truth = nlohmann::json::parse(dg::read_text_file(dir / (id + ".json")));
  try {
    const dg::PixelInference result = dg::infer_pixel_lsystem(dg::read_png(dir / (id + ".png")));
    compare(result.inferred, id, truth["png"]["px_per_unit"].get<double>(), f);
  } catch (const dg::InputError& error) {
    f.failure = error.what();
  }
  return f;
}

std::string row(const std::string& id, const std::string& input, const Figures& f) {
  std::ostringstream out;
  out.precision(3);
  out << "| " << id << " | " << input << " | ";
  if (!f.inferred) {
    out << "no result: " << f.failure << " | | | | | |";
    return out.str();
  }
  out << f.method << " | " << f.hausdorff_percent << " | " << f.length << " (" << f.gt_length << ") | ";
  if (f.angle_error >= 0) out << f.angle_error;
  else out << "–";
  out << " | ";
  if (f.scale_error >= 0) out << f.scale_error;
  else out << "–";
  out << " | " << f.seconds << " |";
  return out.str();
}

void check_targets(const std::string& id, const Figures& f) {
  INFO(id << "\n" << f.text << f.failure);
  REQUIRE(f.inferred);
  const bool jittered = id.rfind("noise_", 0) == 0;
  if (!jittered) CHECK(f.hausdorff_percent < 1.0);
  CHECK(f.length <= f.gt_length + 2);
  if (f.angle_error >= 0) CHECK(f.angle_error < (jittered ? 3.0 : 1.0));
  if (f.scale_error >= 0) CHECK(f.scale_error < 0.05);
}

// PNG cases that meet every target.
const std::vector<std::string> png_cases = {"shuffled_koch_snowflake_n3"};

}  // namespace

TEST_CASE("pixel inference: PNG corpus cases that meet the targets", "[pixel][grammar][corpus]") {
  if (dg::test::lsystem_corpus_cases().empty()) {
    WARN("corpus absent: " << dg::test::lsystem_corpus_dir().string());
    return;
  }
  for (const std::string& id : png_cases) {
    const Figures f = measure_png(id);
    CHECK(f.method == "instance tree");
    check_targets(id, f);
  }
}

TEST_CASE("instance tree: shuffled segments give the same grammar", "[pixel][grammar][corpus]") {
  for (const std::string id : {"koch_snowflake_n4", "plant_124a_d25.7_n5", "plant_124e_d25.7_n5"}) {
    const fs::path svg = dg::test::lsystem_corpus_dir() / (id + ".svg");
    if (!fs::exists(svg)) {
      WARN("corpus absent: " << svg.string());
      continue;
    }
    dg::SvgDrawing drawing = dg::read_svg(svg);
    const std::string original = dg::infer_drawing_lsystem(drawing).text;
    std::mt19937 random(11);
    std::shuffle(drawing.elements.begin(), drawing.elements.end(), random);
    INFO(id);
    CHECK(dg::infer_drawing_lsystem(drawing).text == original);
  }
}

// All cases, SVG and PNG side by side; slow (the vector path on pixel pieces takes up to a
// minute per case), so hidden: run with `dockgrammar-tests "[pixel-table]"`.
TEST_CASE("pixel inference: corpus table", "[.][pixel-table][corpus]") {
  std::ostringstream table;
  table << "| case | input | method | Hausdorff % | length (gt) | angle err ° | scale err | s |\n|---|---|---|---|---|---|---|---|\n";
  for (const std::string& id : dg::test::lsystem_corpus_cases()) {
    table << row(id, "svg", measure_svg(id)) << "\n";
    table << row(id, "png", measure_png(id)) << "\n";
  }
  WARN(table.str());
  SUCCEED();
}
