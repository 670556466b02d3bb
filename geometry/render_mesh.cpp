#include "geometry/render_mesh.h"

#include "geometry/depth_raster.h"
#include "geometry/errors.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace dg {

namespace {

using Vec3f = Eigen::Vector3f;

constexpr std::uint64_t max_samples = std::uint64_t{1} << 28;  // about 3 GB of sample buffers

// What a triangle looks like in the picture: its normal turned towards the viewer, its shaded
// colour, and how many pixel sizes its depth may change from one sample to the next (with slack).
struct Shade {
  Vec3f normal;
  Rgba8 color;
  float depth_step;
};

// The frame in samples and everything the resolve and the overlay passes need from the scene.
struct Scene {
  Camera camera;
  int width = 0, height = 0;  // samples
  double diagonal = 0;        // model bounding-box diagonal, model units
};

void check_options(const TriangleMesh& mesh, const std::vector<Rgba8>& triangle_colors,
                   const std::vector<SceneLine>& lines, const MeshRenderOptions& options) {
  if (options.width < 1 || options.width > 16384 || options.height < 1 || options.height > 16384)
    throw InputError("picture size must be 1..16384 pixels per side, got " + std::to_string(options.width) + "x" +
                     std::to_string(options.height));
  if (options.supersample < 1 || options.supersample > 8)
    throw InputError("supersample must be 1..8, got " + std::to_string(options.supersample));
  const auto samples = static_cast<std::uint64_t>(options.width) * static_cast<std::uint64_t>(options.height) *
                       static_cast<std::uint64_t>(options.supersample * options.supersample);
  if (samples > max_samples)
    throw InputError("picture too large: " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                     " pixels with supersample " + std::to_string(options.supersample) +
                     " need more than 2^28 samples; lower the size or the supersampling");
  if (!(options.camera.margin_fraction >= 0 && options.camera.margin_fraction <= 0.45))
    throw InputError("camera margin must be a fraction in [0, 0.45]");
  if (!(options.crease_degrees >= 0 && options.crease_degrees <= 180))
    throw InputError("crease angle must be 0..180 degrees");
  if (!(options.line_depth_bias >= 0 && std::isfinite(options.line_depth_bias)))
    throw InputError("line depth bias must be a finite fraction >= 0");
  if (!triangle_colors.empty() && triangle_colors.size() != mesh.triangles.size())
    throw InputError("picture needs one colour per triangle: got " + std::to_string(triangle_colors.size()) +
                     " colours for " + std::to_string(mesh.triangles.size()) + " triangles");
  for (const SceneLine& line : lines) {
    if (!(line.width_pixels > 0 && line.width_pixels <= 1000))
      throw InputError("overlay line width must be in (0, 1000] pixels");
    for (const Vec3& p : line.points)
      if (!p.allFinite()) throw InputError("overlay line has a non-finite point");
  }
}

// Bounds of the referenced corners and line points; marks referenced positions in `used`.
BoundingBox scene_bounds(const TriangleMesh& mesh, const std::vector<SceneLine>& lines, std::vector<char>& used) {
  used.assign(mesh.positions.size(), 0);
  for (const Triangle& t : mesh.triangles)
    for (std::uint32_t v : t) {
      if (v >= mesh.positions.size())
        throw InputError("triangle corner index " + std::to_string(v) + " is out of range (" +
                         std::to_string(mesh.positions.size()) + " positions)");
      used[v] = 1;
    }
  BoundingBox box;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v)
    if (used[v]) {
      if (!mesh.positions[v].allFinite()) throw InputError("mesh has a non-finite vertex position");
      box.add(mesh.positions[v]);
    }
  for (const SceneLine& line : lines)
    for (const Vec3& p : line.points) box.add(p);
  if (!std::isfinite(box.diagonal())) throw InputError("picture: model coordinates are too large");
  return box;
}

// Projects the positions with an aimed camera, fits the camera to the referenced ones and the
// line points, and returns the positions in sample coordinates (x, y, key).
std::vector<Vec3> fit_and_project(const TriangleMesh& mesh, const std::vector<char>& used,
                                  const std::vector<SceneLine>& lines, const MeshRenderOptions& options, Scene& scene) {
  std::vector<Vec3> projected(mesh.positions.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, projected.size(), 4096), [&](const auto& range) {
    for (std::size_t v = range.begin(); v < range.end(); ++v) projected[v] = scene.camera.project(mesh.positions[v]);
  });
  Vec2 low = Vec2::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (std::size_t v = 0; v < projected.size(); ++v)
    if (used[v]) low = low.cwiseMin(projected[v].head<2>()), high = high.cwiseMax(projected[v].head<2>());
  for (const SceneLine& line : lines)
    for (const Vec3& p : line.points) {
      const Vec2 q = scene.camera.project(p).head<2>();
      low = low.cwiseMin(q), high = high.cwiseMax(q);
    }
  frame_camera(scene.camera, low, high, scene.width, scene.height, options.camera.margin_fraction);
  for (Vec3& p : projected) p.head<2>() = scene.camera.scale * p.head<2>() + scene.camera.offset;
  return projected;
}

// Depth change, in pixel sizes, that a continuous surface with this facing normal shows from
// one sample to the next, with slack for rounding.
float depth_step(const Vec3& normal, const Camera& camera) {
  const double facing = std::max(0.05, normal.dot(camera.toward));
  const double slope = std::max(std::abs(normal.dot(camera.right)), std::abs(normal.dot(camera.up))) / facing;
  return static_cast<float>(1.5 * slope + 1.5);
}

// Facing normal and shaded colour of every triangle: two-sided Lambert plus ambient, with
// the light left of and a little above the viewer.
std::vector<Shade> shade_triangles(const TriangleMesh& mesh, const std::vector<Rgba8>& triangle_colors,
                                   const MeshRenderOptions& options, const Camera& camera) {
  const Vec3 light = (camera.toward + 0.25 * camera.up - 0.5 * camera.right).normalized();
  std::vector<Shade> shades(mesh.triangles.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, shades.size(), 4096), [&](const auto& range) {
    for (std::size_t t = range.begin(); t < range.end(); ++t) {
      const auto corners = mesh.corners(t);
      Vec3 normal = mesh.area_vector(t).normalized();
      if (!normal.allFinite()) normal = camera.toward;
      if (normal.dot(camera.to_viewer((corners[0] + corners[1] + corners[2]) / 3)) < 0) normal = -normal;
      const double lambert = std::max(0.0, normal.dot(light));
      // Light adds up in linear intensity; 1/2.2 maps it back to sRGB-like pixel values.
      const double brightness = std::pow(0.22 + 0.78 * lambert, 1 / 2.2);
      const Rgba8 base = triangle_colors.empty() ? options.default_color : triangle_colors[t];
      const auto channel = [&](std::uint8_t c) {
        return static_cast<std::uint8_t>(std::lround(std::clamp(c * brightness, 0.0, 255.0)));
      };
      shades[t] = {normal.cast<float>(), {channel(base.r), channel(base.g), channel(base.b), 255},
                   depth_step(normal, camera)};
    }
  });
  return shades;
}

// True when sample i (showing triangle t) lies on an outline: next to the background, on the
// near side of a depth jump, or at a crease.
bool on_edge(const DepthRaster& raster, const std::vector<Shade>& shades, const Camera& camera, double cos_crease,
             int x, int y) {
  const std::size_t i = raster.index(x, y);
  const std::uint32_t t = raster.triangle[i];
  const double distance = camera.distance(raster.key[i]);
  const double pixel_size = camera.pixel_size(raster.key[i]);
  const int offsets[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (const auto& o : offsets) {
    const int nx = x + o[0], ny = y + o[1];
    if (nx < 0 || ny < 0 || nx >= raster.width || ny >= raster.height) continue;
    const std::size_t n = raster.index(nx, ny);
    const std::uint32_t u = raster.triangle[n];
    if (u == t) continue;
    if (u == DepthRaster::none) return true;
    const double jump = camera.distance(raster.key[n]) - distance;
    const double tolerance = pixel_size * std::max(shades[t].depth_step, shades[u].depth_step);
    if (jump > tolerance) return true;
    if (jump >= -tolerance && shades[t].normal.dot(shades[u].normal) < cos_crease) return true;
  }
  return false;
}

// Colours every sample: shaded triangle colour (darkened on outlines) or the background.
Image resolve(const DepthRaster& raster, const std::vector<Shade>& shades, const Camera& camera,
              const MeshRenderOptions& options) {
  Image samples(raster.width, raster.height, options.background);
  const double cos_crease = std::cos(options.crease_degrees * std::numbers::pi / 180);
  constexpr int edge_weight = 200;  // of 256
  tbb::parallel_for(0, raster.height, [&](int y) {
    for (int x = 0; x < raster.width; ++x) {
      const std::uint32_t t = raster.triangle[raster.index(x, y)];
      if (t == DepthRaster::none) continue;
      Rgba8 color = shades[t].color;
      if (options.draw_edges && on_edge(raster, shades, camera, cos_crease, x, y)) {
        const auto mix = [](std::uint8_t a, std::uint8_t b) {
          return static_cast<std::uint8_t>((a * (256 - edge_weight) + b * edge_weight + 128) / 256);
        };
        color = {mix(color.r, options.edge_color.r), mix(color.g, options.edge_color.g),
                 mix(color.b, options.edge_color.b), 255};
      }
      samples.at(x, y) = color;
    }
  });
  return samples;
}

// Draws one overlay line into the sample image, anti-aliased, hidden behind nearer surface
// samples unless its depth test is off. Each sample takes the largest coverage of any segment.
void draw_scene_line(Image& samples, const DepthRaster& raster, const Scene& scene, const SceneLine& line,
                     double width_samples, double bias) {
  if (line.points.empty()) return;
  std::vector<Vec3> points;
  points.reserve(line.points.size());
  for (const Vec3& p : line.points) points.push_back(scene.camera.project(p));
  const double reach = width_samples / 2 + 0.5;
  Vec2 low = points.front().head<2>(), high = low;
  for (const Vec3& p : points) low = low.cwiseMin(p.head<2>()), high = high.cwiseMax(p.head<2>());
  const int x0 = std::max(0, static_cast<int>(std::floor(low.x() - reach)));
  const int y0 = std::max(0, static_cast<int>(std::floor(low.y() - reach)));
  const int x1 = std::min(samples.width - 1, static_cast<int>(std::ceil(high.x() + reach)));
  const int y1 = std::min(samples.height - 1, static_cast<int>(std::ceil(high.y() + reach)));
  if (x0 > x1 || y0 > y1) return;
  const int columns = x1 - x0 + 1;
  std::vector<float> coverage(static_cast<std::size_t>(columns) * static_cast<std::size_t>(y1 - y0 + 1), 0.0f);
  const std::size_t segments = points.size() == 1 ? 1 : points.size() - 1;
  for (std::size_t s = 0; s < segments; ++s) {
    const Vec3& a = points[s];
    const Vec3& b = points[std::min(s + 1, points.size() - 1)];
    const Vec2 ab = (b - a).head<2>();
    const double length2 = ab.squaredNorm();
    const int sx0 = std::max(x0, static_cast<int>(std::floor(std::min(a.x(), b.x()) - reach)));
    const int sy0 = std::max(y0, static_cast<int>(std::floor(std::min(a.y(), b.y()) - reach)));
    const int sx1 = std::min(x1, static_cast<int>(std::ceil(std::max(a.x(), b.x()) + reach)));
    const int sy1 = std::min(y1, static_cast<int>(std::ceil(std::max(a.y(), b.y()) + reach)));
    for (int y = sy0; y <= sy1; ++y)
      for (int x = sx0; x <= sx1; ++x) {
        const Vec2 p(x + 0.5, y + 0.5);
        const double t = length2 > 0 ? std::clamp((p - a.head<2>()).dot(ab) / length2, 0.0, 1.0) : 0.0;
        const double c = std::clamp(reach - (p - (a.head<2>() + t * ab)).norm(), 0.0, 1.0);
        if (c <= 0) continue;
        if (line.depth_test) {
          const std::size_t i = raster.index(x, y);
          const double key = a.z() + t * (b.z() - a.z());
          if (raster.triangle[i] != DepthRaster::none &&
              scene.camera.distance(key) > scene.camera.distance(raster.key[i]) + bias)
            continue;
        }
        float& slot = coverage[static_cast<std::size_t>(y - y0) * columns + (x - x0)];
        slot = std::max(slot, static_cast<float>(c));
      }
  }
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x)
      blend_pixel(samples, x, y, line.color, coverage[static_cast<std::size_t>(y - y0) * columns + (x - x0)]);
}

// Averages factor x factor blocks of samples into pixels: colours weighted by alpha, or plain
// averages where every sample is fully transparent.
Image downsample(const Image& samples, int factor) {
  Image picture(samples.width / factor, samples.height / factor, Rgba8{});
  const auto count = static_cast<std::uint64_t>(factor * factor);
  tbb::parallel_for(0, picture.height, [&](int y) {
    for (int x = 0; x < picture.width; ++x) {
      std::uint64_t r = 0, g = 0, b = 0, a = 0, plain_r = 0, plain_g = 0, plain_b = 0;
      for (int sy = y * factor; sy < (y + 1) * factor; ++sy)
        for (int sx = x * factor; sx < (x + 1) * factor; ++sx) {
          const Rgba8& s = samples.at(sx, sy);
          r += std::uint64_t{s.r} * s.a, g += std::uint64_t{s.g} * s.a, b += std::uint64_t{s.b} * s.a, a += s.a;
          plain_r += s.r, plain_g += s.g, plain_b += s.b;
        }
      const auto average = [](std::uint64_t sum, std::uint64_t n) { return static_cast<std::uint8_t>((sum + n / 2) / n); };
      picture.at(x, y) = a > 0 ? Rgba8{average(r, a), average(g, a), average(b, a), average(a, count)}
                               : Rgba8{average(plain_r, count), average(plain_g, count), average(plain_b, count), 0};
    }
  });
  return picture;
}

}  // namespace

Image render_mesh(const TriangleMesh& mesh, const std::vector<Rgba8>& triangle_colors,
                  const std::vector<SceneLine>& lines, const MeshRenderOptions& options) {
  check_options(mesh, triangle_colors, lines, options);
  std::vector<char> used;
  const BoundingBox box = scene_bounds(mesh, lines, used);
  Scene scene;
  scene.camera = aim_camera(box, options.camera);
  scene.width = options.width * options.supersample;
  scene.height = options.height * options.supersample;
  scene.diagonal = box.diagonal();
  const std::vector<Vec3> projected = fit_and_project(mesh, used, lines, options, scene);

  const DepthRaster raster = rasterize_depth(projected, mesh.triangles, scene.width, scene.height);
  const std::vector<Shade> shades = shade_triangles(mesh, triangle_colors, options, scene.camera);
  Image samples = resolve(raster, shades, scene.camera, options);
  for (const SceneLine& line : lines)
    draw_scene_line(samples, raster, scene, line, line.width_pixels * options.supersample,
                    options.line_depth_bias * scene.diagonal);
  return downsample(samples, options.supersample);
}

Image render_views(const TriangleMesh& mesh, const std::vector<Rgba8>& triangle_colors,
                   const std::vector<SceneLine>& lines, const MeshRenderOptions& options) {
  if (options.width < 2 || options.height < 2 || options.width > 16384 || options.height > 16384)
    throw InputError("contact sheet size must be 2..16384 pixels per side, got " + std::to_string(options.width) +
                     "x" + std::to_string(options.height));
  Image sheet(options.width, options.height, options.background);
  const double views[4][2] = {{0, 0}, {90, 0}, {0, 90}, {options.camera.azimuth_degrees, options.camera.elevation_degrees}};
  MeshRenderOptions cell = options;
  cell.width = options.width / 2;
  cell.height = options.height / 2;
  for (int v = 0; v < 4; ++v) {
    cell.camera.azimuth_degrees = views[v][0];
    cell.camera.elevation_degrees = views[v][1];
    const Image picture = render_mesh(mesh, triangle_colors, lines, cell);
    const int left = (v % 2) * cell.width, top = (v / 2) * cell.height;
    for (int y = 0; y < picture.height; ++y)
      for (int x = 0; x < picture.width; ++x) sheet.at(left + x, top + y) = picture.at(x, y);
  }
  return sheet;
}

void write_mesh_picture(const std::filesystem::path& png, const TriangleMesh& mesh,
                        const std::vector<Rgba8>& triangle_colors, const std::vector<SceneLine>& lines,
                        const MeshRenderOptions& options) {
  write_png(png, render_mesh(mesh, triangle_colors, lines, options));
}

}  // namespace dg
