#include "synthesis/render.h"

#include "geometry/image.h"
#include "support/cli_run.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

namespace {

dg::Stroke segment(dg::Vec2 a, dg::Vec2 b, std::size_t index) {
  dg::Stroke s;
  s.path.commands.push_back({dg::PathCommand::Type::Move, {a, dg::Vec2::Zero(), dg::Vec2::Zero()}});
  s.path.commands.push_back({dg::PathCommand::Type::Line, {b, dg::Vec2::Zero(), dg::Vec2::Zero()}});
  s.module_index = index;
  return s;
}

}  // namespace

TEST_CASE("SVG output has one element per stroke, a fitted viewBox and y pointing down", "[synthesis]") {
  dg::Drawing drawing;
  drawing.strokes.push_back(segment({0, 0}, {100, 0}, 0));
  drawing.strokes.push_back(segment({100, 0}, {100, 50}, 2));
  dg::RenderOptions options;
  options.margin_fraction = 0.1;
  const std::string svg = dg::format_svg(drawing, options);
  CHECK(svg.find("viewBox=\"0 0 120 70\"") != std::string::npos);
  CHECK(svg.find("<path d=\"M 10 60 L 110 60\"/>") != std::string::npos);
  CHECK(svg.find("<path d=\"M 110 60 L 110 10\"/>") != std::string::npos);
  const std::regex element("<path ");
  CHECK(std::distance(std::sregex_iterator(svg.begin(), svg.end(), element), std::sregex_iterator()) == 2);
}

TEST_CASE("PNG rasterization draws anti-aliased black lines on white", "[synthesis]") {
  dg::Drawing drawing;
  drawing.strokes.push_back(segment({0, 0}, {100, 0}, 0));
  drawing.strokes.push_back(segment({0, 0}, {0, 50}, 1));
  dg::RenderOptions options;
  options.long_side_px = 200;
  const dg::Image image = dg::rasterize(drawing, options);
  CHECK(image.width == 200);
  CHECK(image.height == Approx(200 * 54.0 / 104.0).margin(1));
  // The horizontal line is near the bottom (y up in the drawing, down in the image).
  const int row = static_cast<int>(std::lround(image.height - 200 * 2.0 / 104.0 - 0.5));
  CHECK(image.at(100, row).r < 80);
  CHECK(image.at(100, 5) == dg::Rgba8{255, 255, 255, 255});
  bool partial = false;  // some edge pixels are grey: anti-aliased
  for (int y = 0; y < image.height; ++y)
    partial = partial || (image.at(100, y).r > 20 && image.at(100, y).r < 235);
  CHECK(partial);
}

TEST_CASE("images blend lines and encode to PNG files atomically", "[synthesis]") {
  dg::Image image(20, 10, dg::Rgba8{255, 255, 255, 255});
  dg::draw_line(image, {2, 5}, {18, 5}, 2.0, dg::Rgba8{255, 0, 0, 255});
  CHECK(image.at(10, 4) == dg::Rgba8{255, 0, 0, 255});
  CHECK(image.at(10, 0) == dg::Rgba8{255, 255, 255, 255});
  dg::blend_pixel(image, 0, 0, dg::Rgba8{0, 0, 0, 255}, 0.5);
  CHECK(static_cast<int>(image.at(0, 0).g) == Approx(128).margin(1));
  dg::blend_pixel(image, -1, 50, dg::Rgba8{0, 0, 0, 255}, 1.0);  // outside: ignored

  const std::vector<unsigned char> bytes = dg::encode_png(image);
  REQUIRE(bytes.size() > 8);
  CHECK(bytes[1] == 'P');
  CHECK(bytes[2] == 'N');
  CHECK(bytes[3] == 'G');
  const std::filesystem::path folder = dg::test::fresh_folder("dockgrammar-png-writer-test");
  const std::filesystem::path file = folder / "line.png";
  dg::write_png(file, image);
  CHECK(std::filesystem::file_size(file) == bytes.size());
  CHECK(std::distance(std::filesystem::directory_iterator(folder), std::filesystem::directory_iterator()) == 1);
  std::filesystem::remove_all(folder);
}
