// fence(n): end post, rail bay, n x (inner post, rail bay), end post, along +x.
//
// Posts stand at x = k * pitch, k = 0 .. n+1; k = 0 and k = n+1 are the END posts (wider,
// taller, with a cap), k = 1 .. n the INNER posts. Two rails run through all posts. The
// repeated unit k (k = 0 .. n-1) is inner post k+1 with the rails from the middle of the bay on
// its left to the middle of the bay on its right, i.e. the slab
// x in [(k + 0.5) pitch, (k + 1.5) pitch). count = n, so fence(n) resized by +m is fence(n+m).
//
// With after_gate = m > 0 the post at x = (n+1) pitch is the first of two GATE posts (end posts):
// a gate leaf, fused to both, fills the opening of kGateOpening pitches to the second gate post,
// after which the fence goes on with m inner posts and an end post (the same bays and rails).
// That second stretch is a repetition of its own, posts_after_gate, count m.

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
constexpr double kGateOpening = 1.5;  // pitches between the two gate posts
constexpr double kLeafDepth = 0.03;   // along y
constexpr double kLeafBottom = 0.15;
constexpr double kLeafTop = 1.15;

/// Adds a post centred at x with a square section of `width` from z = 0 to `height`.
void add_post(BoxSolid& solid, double x, double width, double height) {
  add_box(solid, Vec3(x - width / 2, -width / 2, 0.0), Vec3(x + width / 2, width / 2, height));
}

/// Adds an end post with its cap at x.
void add_end_post(BoxSolid& solid, double x) {
  add_post(solid, x, kEndPostWidth, kEndPostHeight);
  add_box(solid, Vec3(x - kCapWidth / 2, -kCapWidth / 2, kEndPostHeight),
          Vec3(x + kCapWidth / 2, kCapWidth / 2, kEndPostHeight + kCapHeight));
}

/// Adds a stretch of fence from x = start: an end post, `inner` inner posts one pitch apart, an
/// end post, the two rails between the end posts, and seams in the middle of every bay.
void add_stretch(BoxSolid& solid, double start, int inner, double pitch) {
  for (int k = 0; k <= inner + 1; ++k) {
    const double x = start + k * pitch;
    if (k == 0 || k == inner + 1)
      add_end_post(solid, x);
    else
      add_post(solid, x, kInnerPostWidth, kInnerPostHeight);
  }
  const double end = start + (inner + 1) * pitch;
  for (double bottom : {kLowerRail, kUpperRail})
    add_box(solid, Vec3(start, -kRailDepth / 2, bottom), Vec3(end, kRailDepth / 2, bottom + kRailHeight));
  for (int k = 0; k <= inner; ++k) add_seam(solid, 0, start + (k + 0.5) * pitch);
}

/// The repetition of a stretch's inner posts whose first end post stands at x = start; `count`
/// names the parameter that sets their number in the unit's description.
Repetition stretch_posts(std::string name, const TriangleMesh& mesh, double start, int inner, double pitch,
                         const std::string& count) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::string at = start == 0.0 ? "" : fmt::format("{} + ", start);
  Repetition posts = translation_repetition(
      std::move(name), Vec3(pitch, 0.0, 0.0), inner,
      fmt::format("inner post k+1 (x = {0}(k+1)*pitch) with both rails from mid-bay to mid-bay, x in [{0}(k+0.5)*pitch, "
                  "{0}(k+1.5)*pitch); count = {1} inner posts (the 2 end posts and {1}+1 rail bays are not counted)",
                  at, count));
  posts.measure = measure_unit(mesh, box_region(Vec3(start + 0.5 * pitch, -inf, -inf), Vec3(start + 1.5 * pitch, inf, inf)));
  return posts;
}

}  // namespace

Asset make_fence(const nlohmann::json& params) {
  Parameters p = read_parameters("fence", params);
  const int n = integer_parameter(p, "n", 4, 1, 10000);
  const double pitch = number_parameter(p, "pitch", 2.0, 0.5, 100.0);
  const int detail = integer_parameter(p, "detail", 1, 1, 1000);
  const int after_gate = integer_parameter(p, "after_gate", 0, 0, 10000);
  reject_unknown_parameters(p);

  BoxSolid solid;
  add_stretch(solid, 0.0, n, pitch);
  const double gate_post = (n + 1) * pitch, second_start = gate_post + kGateOpening * pitch;
  if (after_gate > 0) {
    add_box(solid, Vec3(gate_post, -kLeafDepth / 2, kLeafBottom), Vec3(second_start, kLeafDepth / 2, kLeafTop));
    add_stretch(solid, second_start, after_gate, pitch);
  }
  TriangleMesh mesh = box_solid_surface(solid, detail);

  std::vector<Repetition> repetitions{stretch_posts("posts", mesh, 0.0, n, pitch, "n")};
  if (after_gate > 0) repetitions.push_back(stretch_posts("posts_after_gate", mesh, second_start, after_gate, pitch, "after_gate"));
  nlohmann::json parts = {{"end_posts", 2}, {"inner_posts", n}, {"rail_bays", n + 1}, {"rails", 2}};
  std::string description = "fence along +x, posts at x = k*pitch (k = 0..n+1), end posts wider and taller with a cap";
  if (after_gate > 0) {
    parts = {{"end_posts", 4}, {"inner_posts", n + after_gate}, {"rail_bays", n + after_gate + 2}, {"rails", 4}, {"gate_leaves", 1}};
    description += fmt::format("; a gate leaf from x = {} to {}, then end post, {} inner posts and end post", gate_post,
                               second_start, after_gate);
  }
  const nlohmann::json notes = {{"parts", parts}, {"description", description}};
  const std::string name = after_gate > 0 ? fmt::format("fence_{}_gate_{}", n, after_gate) : fmt::format("fence_{}", n);
  return finish_asset(name, p, std::move(mesh), std::move(repetitions), nullptr, notes);
}

}  // namespace dg::assets
