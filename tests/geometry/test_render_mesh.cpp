#include "geometry/render_mesh.h"

#include "geometry/errors.h"
#include "support/shapes.h"
#include "support/cli_run.h"

#include <catch2/catch.hpp>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

namespace {

using dg::Rgba8;
using dg::Vec3;

const Rgba8 white{255, 255, 255, 255};
const Rgba8 red{220, 30, 30, 255};
const Rgba8 blue{30, 30, 220, 255};
const Rgba8 green{0, 200, 0, 255};

bool reddish(Rgba8 p) { return p.r > 100 && p.r > 2 * p.g && p.r > 2 * p.b; }
bool bluish(Rgba8 p) { return p.b > 100 && p.b > 2 * p.r && p.b > 2 * p.g; }
bool greenish(Rgba8 p) { return p.g > 120 && p.g > 2 * p.r && p.g > 2 * p.b; }

std::size_t count_not(const dg::Image& image, Rgba8 background) {
  return static_cast<std::size_t>(std::count_if(image.pixels.begin(), image.pixels.end(),
                                                [&](Rgba8 p) { return p != background; }));
}

// Small front view (looking along -z at a y-up model) without outlines.
dg::MeshRenderOptions front_view() {
  dg::MeshRenderOptions options;
  options.width = 200;
  options.height = 150;
  options.camera.azimuth_degrees = 0;
  options.camera.elevation_degrees = 0;
  options.draw_edges = false;
  return options;
}

// A red box in front (z in [1, 2]) of a larger blue box (z in [-2, -1]); `red_first` sets the
// triangle order so the test shows that depth, not drawing order, decides.
std::pair<dg::TriangleMesh, std::vector<Rgba8>> red_before_blue(bool red_first) {
  const dg::TriangleMesh front = dg::test::make_box(Vec3(-0.5, -0.5, 1), Vec3(0.5, 0.5, 2));
  const dg::TriangleMesh back = dg::test::make_box(Vec3(-2, -1, -2), Vec3(2, 1, -1));
  dg::TriangleMesh mesh;
  std::vector<Rgba8> colors;
  for (bool red_part : {red_first, !red_first}) {
    dg::test::append(mesh, red_part ? front : back);
    colors.insert(colors.end(), 12, red_part ? red : blue);
  }
  return {mesh, colors};
}

}  // namespace

TEST_CASE("a red cube on white fills the middle and leaves the corners white", "[geometry][render]") {
  const dg::TriangleMesh cube = dg::test::make_box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  dg::MeshRenderOptions options;
  options.width = 240;
  options.height = 180;
  const dg::Image image = dg::render_mesh(cube, std::vector<Rgba8>(12, red), {}, options);
  REQUIRE(image.width == 240);
  REQUIRE(image.height == 180);
  CHECK(image.at(0, 0) == white);
  CHECK(image.at(239, 0) == white);
  CHECK(image.at(0, 179) == white);
  CHECK(image.at(239, 179) == white);
  int red_near_centre = 0;
  for (int y = 80; y < 100; ++y)
    for (int x = 110; x < 130; ++x) red_near_centre += reddish(image.at(x, y));
  CHECK(red_near_centre > 350);  // of 400; crease outlines may cross the centre
  // The projected cube is a hexagon about as tall as the frame minus its margins.
  const double covered = static_cast<double>(count_not(image, white)) / static_cast<double>(image.pixels.size());
  CHECK(covered > 0.3);
  CHECK(covered < 0.7);
}

TEST_CASE("the z-buffer shows the nearer cube where two cubes overlap", "[geometry][render]") {
  for (bool red_first : {true, false}) {
    const auto [mesh, colors] = red_before_blue(red_first);
    const dg::Image image = dg::render_mesh(mesh, colors, {}, front_view());
    CHECK(reddish(image.at(100, 75)));  // centre: both boxes, red is nearer
    CHECK(bluish(image.at(30, 75)));    // left: only the blue box
    CHECK(image.at(2, 2) == white);
  }
}

TEST_CASE("overlay lines appear on top, and depth-tested lines hide behind nearer surfaces", "[geometry][render]") {
  const auto [mesh, colors] = red_before_blue(true);
  dg::SceneLine across{{Vec3(-1.8, 0, 3), Vec3(1.8, 0, 3)}, green, 3};  // in front of everything
  dg::SceneLine behind{{Vec3(-1.8, 0.25, 0), Vec3(1.8, 0.25, 0)}, green, 3};  // between the boxes
  const dg::MeshRenderOptions options = front_view();
  const dg::Image base = dg::render_mesh(mesh, colors, {}, options);

  const dg::Image crossed = dg::render_mesh(mesh, colors, {across}, options);
  CHECK(greenish(crossed.at(100, 75)));
  CHECK(greenish(crossed.at(40, 75)));

  const dg::Image hidden = dg::render_mesh(mesh, colors, {behind}, options);
  // The 4 units wide blue box fills the width up to the margins; pixel row y is centred on the line.
  const double pixels_per_unit = options.width * (1 - 2 * options.camera.margin_fraction) / 4;
  const int y = static_cast<int>(75 - 0.25 * pixels_per_unit);
  CHECK(reddish(hidden.at(100, y)));  // the red box hides it
  CHECK(greenish(hidden.at(40, y)));  // in front of the blue box
  CHECK(hidden.at(100, y) == base.at(100, y));

  behind.depth_test = false;
  const dg::Image on_top = dg::render_mesh(mesh, colors, {behind}, options);
  CHECK(greenish(on_top.at(100, y)));
}

TEST_CASE("a curve lying on a sphere shows in front and hides behind it", "[geometry][render]") {
  const dg::TriangleMesh sphere = dg::test::make_sphere(Vec3(0, 0, 0), 1, 16, 32);  // poles on z
  dg::SceneLine equator{{}, green, 3};
  for (std::uint32_t v = 1 + 7 * 32; v < 1 + 8 * 32; ++v) equator.points.push_back(sphere.positions[v]);
  equator.points.push_back(equator.points.front());
  dg::MeshRenderOptions options = front_view();
  options.camera.up = Vec3(0, 0, 1);
  options.camera.elevation_degrees = 30;
  const dg::Image image = dg::render_mesh(sphere, std::vector<Rgba8>(sphere.triangles.size(), red), {equator}, options);
  // Seen from 30 degrees up, the equator's front point lies half a radius below the centre and
  // its back point half a radius above it, where the sphere hides it.
  const int half_radius = static_cast<int>(std::lround(0.25 * options.height * (1 - 2 * options.camera.margin_fraction)));
  CHECK(greenish(image.at(100, 75 + half_radius)));
  CHECK(reddish(image.at(100, 75 - half_radius)));
}

TEST_CASE("mesh pictures are identical across runs and thread counts", "[geometry][render]") {
  dg::TriangleMesh mesh = dg::test::make_sphere(Vec3(0, 0, 0), 1, 40, 80);
  dg::test::append(mesh, dg::test::make_box(Vec3(0.5, -1.5, -0.3), Vec3(1.5, 1.5, 0.3)));
  std::vector<Rgba8> colors(mesh.triangles.size(), red);
  for (std::size_t t = 0; t < colors.size(); t += 3) colors[t] = blue;
  const std::vector<dg::SceneLine> lines{{{Vec3(-1, -1, 1), Vec3(1, 1, 1), Vec3(1, -1, -1)}, green, 2.5}};
  dg::MeshRenderOptions options;
  options.width = 320;
  options.height = 240;
  options.camera.field_of_view_degrees = 30;
  const dg::Image first = dg::render_mesh(mesh, colors, lines, options);
  CHECK(dg::render_mesh(mesh, colors, lines, options).pixels == first.pixels);
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  CHECK(dg::render_mesh(mesh, colors, lines, options).pixels == first.pixels);
}

TEST_CASE("the camera keeps the model's up axis pointing up in the picture", "[geometry][render]") {
  // A box long along y is tall in a y-up front view. Treated as z-up and seen from +x
  // (azimuth 90), y runs from left to right, so the same box looks wide.
  const dg::TriangleMesh tower = dg::test::make_box(Vec3(0, 0, 0), Vec3(1, 4, 1));
  const auto extent = [](const dg::Image& image) {
    int x0 = image.width, x1 = -1, y0 = image.height, y1 = -1;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        if (image.at(x, y) != white) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    return std::pair{x1 - x0 + 1, y1 - y0 + 1};
  };
  dg::MeshRenderOptions options = front_view();
  const auto [y_up_width, y_up_height] = extent(dg::render_mesh(tower, {}, {}, options));
  CHECK(y_up_height > 3 * y_up_width);
  options.camera.up = Vec3(0, 0, 1);
  options.camera.azimuth_degrees = 90;  // from +x: y runs left to right
  const auto [z_up_width, z_up_height] = extent(dg::render_mesh(tower, {}, {}, options));
  CHECK(z_up_width > 3 * z_up_height);
}

TEST_CASE("outlines darken silhouettes and creases of a default-grey cube", "[geometry][render]") {
  const dg::TriangleMesh cube = dg::test::make_box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  dg::MeshRenderOptions options;
  options.width = 240;
  options.height = 180;
  const dg::Image plain = [&] {
    dg::MeshRenderOptions no_edges = options;
    no_edges.draw_edges = false;
    return dg::render_mesh(cube, {}, {}, no_edges);
  }();
  const dg::Image outlined = dg::render_mesh(cube, {}, {}, options);
  int darker = 0;
  for (std::size_t i = 0; i < plain.pixels.size(); ++i) darker += outlined.pixels[i].r + 20 < plain.pixels[i].r;
  INFO("darker pixels: " << darker);
  CHECK(darker > 200);   // three creases and the hexagon outline, about one pixel wide
  CHECK(darker < 2000);  // but not whole faces
  CHECK(plain.at(120, 90).r == plain.at(120, 90).g);  // default colour is grey
}

TEST_CASE("an empty mesh gives the background, bad input a clear InputError", "[geometry][render]") {
  dg::MeshRenderOptions options = front_view();
  options.background = Rgba8{10, 20, 30, 0};
  const dg::Image empty = dg::render_mesh(dg::TriangleMesh{}, {}, {}, options);
  CHECK(count_not(empty, options.background) == 0);

  const dg::TriangleMesh cube = dg::test::make_box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  CHECK_THROWS_AS(dg::render_mesh(cube, std::vector<Rgba8>(5, red), {}, {}), dg::InputError);
  dg::TriangleMesh broken = cube;
  broken.triangles.push_back({0, 1, 99});
  CHECK_THROWS_AS(dg::render_mesh(broken, {}, {}, {}), dg::InputError);
  broken = cube;
  broken.positions[0].x() = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(dg::render_mesh(broken, {}, {}, {}), dg::InputError);
  dg::MeshRenderOptions bad;
  bad.supersample = 0;
  CHECK_THROWS_AS(dg::render_mesh(cube, {}, {}, bad), dg::InputError);
  bad = {};
  bad.width = bad.height = 16384;
  CHECK_THROWS_AS(dg::render_mesh(cube, {}, {}, bad), dg::InputError);  // too many samples
  bad = {};
  bad.width = 0;
  CHECK_THROWS_AS(dg::render_mesh(cube, {}, {}, bad), dg::InputError);
  bad = {};
  bad.camera.up = Vec3::Zero();
  CHECK_THROWS_AS(dg::render_mesh(cube, {}, {}, bad), dg::InputError);
}

TEST_CASE("a contact sheet shows four views and pictures are written as PNG", "[geometry][render]") {
  const auto [mesh, colors] = red_before_blue(true);
  dg::MeshRenderOptions options;
  options.width = 200;
  options.height = 160;
  const dg::Image sheet = dg::render_views(mesh, colors, {}, options);
  REQUIRE(sheet.width == 200);
  REQUIRE(sheet.height == 160);
  for (int cell = 0; cell < 4; ++cell) {
    int covered = 0;
    for (int y = (cell / 2) * 80; y < (cell / 2 + 1) * 80; ++y)
      for (int x = (cell % 2) * 100; x < (cell % 2 + 1) * 100; ++x) covered += sheet.at(x, y) != white;
    CHECK(covered > 1000);  // of 8000: every view shows the model
  }
  CHECK(reddish(sheet.at(50, 40)));  // front view: the red box covers the middle
  // Top view (bottom left): the red box, nearer the front (+z), is drawn below the blue one.
  int red_row = -1, blue_row = -1;
  for (int y = 80; y < 160; ++y) {
    if (reddish(sheet.at(50, y))) red_row = y;
    if (bluish(sheet.at(50, y)) && blue_row < 0) blue_row = y;
  }
  CHECK(blue_row > 80);
  CHECK(red_row > blue_row);

  const auto directory = dg::test::fresh_folder("dockgrammar-render-test");
  const auto png = directory / "boxes.png";
  dg::write_mesh_picture(png, mesh, colors, {}, options);
  std::ifstream in(png, std::ios::binary);
  char signature[8] = {};
  in.read(signature, 8);
  CHECK(std::string(signature + 1, 3) == "PNG");
  std::filesystem::remove_all(directory);
}
