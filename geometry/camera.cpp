#include "geometry/camera.h"

#include "geometry/errors.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dg {

namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// The model's "right" axis: the x axis made perpendicular to up (y when up is along x).
Vec3 reference_right(const Vec3& up) {
  for (const Vec3& axis : {Vec3(Vec3::UnitX()), Vec3(Vec3::UnitY())}) {
    const Vec3 r = axis - axis.dot(up) * up;
    if (r.norm() > 0.1) return r.normalized();
  }
  return Vec3::UnitZ();  // unreachable for a unit up: x and y cannot both be parallel to it
}

}  // namespace

Vec3 Camera::project(const Vec3& p) const {
  const Vec3 d = p - origin;
  if (!perspective) return {offset.x() + scale * d.dot(right), offset.y() - scale * d.dot(up), d.dot(toward)};
  const double depth = -d.dot(toward);
  return {offset.x() + scale * d.dot(right) / depth, offset.y() - scale * d.dot(up) / depth, 1.0 / depth};
}

double Camera::distance(double key) const { return perspective ? 1.0 / key : -key; }

double Camera::pixel_size(double key) const { return perspective ? distance(key) / scale : 1.0 / scale; }

Vec3 Camera::to_viewer(const Vec3& p) const { return perspective ? Vec3((origin - p).normalized()) : toward; }

Camera aim_camera(const BoundingBox& box, const CameraSetup& setup) {
  if (!setup.up.allFinite() || !(setup.up.norm() > 0))
    throw InputError("camera up axis must be a finite non-zero vector");
  if (!(setup.field_of_view_degrees >= 0 && setup.field_of_view_degrees < 120))
    throw InputError("camera field of view must be 0 (orthographic) or below 120 degrees");
  if (!std::isfinite(setup.azimuth_degrees) || !std::isfinite(setup.elevation_degrees))
    throw InputError("camera azimuth and elevation must be finite");
  const Vec3 model_up = setup.up.normalized();
  const Vec3 model_right = reference_right(model_up);
  const Vec3 model_front = model_right.cross(model_up);  // +z for y-up, -y for z-up
  const double azimuth = radians(setup.azimuth_degrees);
  const double elevation = radians(std::clamp(setup.elevation_degrees, -90.0, 90.0));

  Camera camera;
  const Vec3 horizontal = std::cos(azimuth) * model_front + std::sin(azimuth) * model_right;
  camera.toward = (std::cos(elevation) * horizontal + std::sin(elevation) * model_up).normalized();
  // up x toward is parallel to this for every elevation below 90 degrees; using it directly
  // keeps the top and bottom views well defined.
  camera.right = (std::cos(azimuth) * model_right - std::sin(azimuth) * model_front).normalized();
  camera.up = camera.toward.cross(camera.right);

  const Vec3 centre = box.empty() ? Vec3::Zero() : Vec3(0.5 * (box.min + box.max));
  camera.perspective = setup.field_of_view_degrees > 0;
  if (!camera.perspective) {
    camera.origin = centre;
  } else {
    const double radius = box.diagonal() > 0 ? 0.5 * box.diagonal() : 1.0;
    camera.origin = centre + camera.toward * (radius / std::sin(radians(setup.field_of_view_degrees) / 2));
  }
  return camera;
}

void frame_camera(Camera& camera, const Vec2& low, const Vec2& high, int width, int height, double margin_fraction) {
  const Vec2 extent = high - low;
  const double usable_x = width * (1 - 2 * margin_fraction);
  const double usable_y = height * (1 - 2 * margin_fraction);
  double scale = std::numeric_limits<double>::infinity();
  if (extent.x() > 0) scale = std::min(scale, usable_x / extent.x());
  if (extent.y() > 0) scale = std::min(scale, usable_y / extent.y());
  if (!std::isfinite(scale)) scale = 1;
  const bool empty = !(low.x() <= high.x() && low.y() <= high.y());
  const Vec2 middle = empty ? Vec2(Vec2::Zero()) : Vec2(0.5 * (low + high));
  camera.scale = scale;
  camera.offset = Vec2(0.5 * width, 0.5 * height) - scale * middle;
}

}  // namespace dg
