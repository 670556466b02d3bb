// fence(n): end post, rail bay, n x (inner post, rail bay), end post, along +x.
//
// Posts stand at x = k * pitch, k = 0 .. n+1; k = 0 and k = n+1 are the END posts (wider,
// taller, with a cap), k = 1 .. n the INNER posts. Two rails run through all posts. The
// repeated unit k (k = 0 .. n-1) is inner post k+1 with the rails from the middle of the bay on
// its left to the middle of the bay on its right, i.e. the slab
// x in [(k + 0.5) pitch, (k + 1.5) pitch). count = n, so fence(n) resized by +m is fence(n+m).

#include "assets/generator/box_solid.h"
#include "assets/generator/ground_truth.h"
#include "assets/generator/models.h"

#include <fmt/format.h>
#include <limits>

namespace dg::assets {

namespace {

constexpr double kInnerPostWidth = 0.10;  // square section, m
constexpr double kInnerPostHeight = 1.20;
constexpr double kEndPostWidth = 0.14;
constexpr double kEndPostHeight = 1.40;
constexpr double kCapWidth = 0.20;
constexpr double kCapHeight = 0.06;
constexpr double kRailDepth = 0.04;   // along y
constexpr double kRailHeight = 0.08;  // along z
constexpr double kLowerRail = 0.30;   // bottom of the lower rail
constexpr double kUpperRail = 0.90;   // bottom of the upper rail

/// Adds a post centred at x with a square section of `width` from z = 0 to `height`.
void add_post(BoxSolid& solid, double x, double width, double height) {
  add_box(solid, Vec3(x - width / 2, -width / 2, 0.0), Vec3(x + width / 2, width / 2, height));
}

}  // namespace

Asset make_fence(const nlohmann::json& params) {
  Parameters p = read_parameters("fence", params);
  const int n = integer_parameter(p, "n", 4, 1, 10000);
  const double pitch = number_parameter(p, "pitch", 2.0, 0.5, 100.0);
  const int detail = integer_parameter(p, "detail", 1, 1, 1000);
  reject_unknown_parameters(p);

  BoxSolid solid;
  for (int k = 0; k <= n + 1; ++k) {
    const double x = k * pitch;
    if (k == 0 || k == n + 1) {
      add_post(solid, x, kEndPostWidth, kEndPostHeight);
      add_box(solid, Vec3(x - kCapWidth / 2, -kCapWidth / 2, kEndPostHeight),
              Vec3(x + kCapWidth / 2, kCapWidth / 2, kEndPostHeight + kCapHeight));
    } else {
      add_post(solid, x, kInnerPostWidth, kInnerPostHeight);
    }
  }
  const double length = (n + 1) * pitch;
  for (double bottom : {kLowerRail, kUpperRail}) {
    add_box(solid, Vec3(0.0, -kRailDepth / 2, bottom), Vec3(length, kRailDepth / 2, bottom + kRailHeight));
  }
  for (int k = 0; k <= n; ++k) add_seam(solid, 0, (k + 0.5) * pitch);
  TriangleMesh mesh = box_solid_surface(solid, detail);

  const double inf = std::numeric_limits<double>::infinity();
  Repetition posts = translation_repetition(
      "posts", Vec3(pitch, 0.0, 0.0), n,
      "inner post k+1 (x = (k+1)*pitch) with both rails from mid-bay to mid-bay, x in [(k+0.5)*pitch, "
      "(k+1.5)*pitch); count = n inner posts (the 2 end posts and n+1 rail bays are not counted)");
  posts.measure = measure_unit(mesh, box_region(Vec3(0.5 * pitch, -inf, -inf), Vec3(1.5 * pitch, inf, inf)));

  const nlohmann::json notes = {
      {"parts",
       {{"end_posts", 2}, {"inner_posts", n}, {"rail_bays", n + 1}, {"rails", 2}}},
      {"description", "fence along +x, posts at x = k*pitch (k = 0..n+1), end posts wider and taller with a cap"}};
  return finish_asset(fmt::format("fence_{}", n), p, std::move(mesh), {posts}, nullptr, notes);
}

}  // namespace dg::assets
