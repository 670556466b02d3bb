#pragma once
// A picture camera for meshes: a view direction around the model, orthographic or mild
// perspective projection, fitted so that the model fills a pixel frame.

#include "geometry/types.h"

namespace dg {

/// Where the camera looks from and how it projects.
struct CameraSetup {
  /// Rotation about `up`, in degrees: 0 looks at the model's front, 90 at its right side.
  /// The front is seen from +z for a y-up model and from -y for a z-up model (in general from
  /// x-axis x up, with the x axis made perpendicular to up), so +x points right at azimuth 0.
  double azimuth_degrees = 35;
  /// Height of the viewpoint above the horizontal plane, in degrees (90 = top view, -90 = bottom).
  double elevation_degrees = 25;
  /// The model's up axis (need not be unit length). Most OBJ/glTF inputs are y-up.
  Vec3 up = Vec3(0, 1, 0);
  /// 0 = orthographic; otherwise the perspective's opening angle across the bounding sphere,
  /// in degrees, in (0, 120) (20-40 looks mild).
  double field_of_view_degrees = 0;
  /// Empty border on every side, as a fraction of the frame's width and height, in [0, 0.45].
  double margin_fraction = 0.04;
};

/// A camera in model space together with the pixel frame it was fitted to.
/// Pixel coordinates: x right, y down, pixel (i, j) covers [i, i+1) x [j, j+1).
struct Camera {
  Vec3 right = Vec3::UnitX();   ///< unit screen-right direction in model space
  Vec3 up = Vec3::UnitY();      ///< unit screen-up direction in model space
  Vec3 toward = Vec3::UnitZ();  ///< unit view axis, pointing from the model to the viewer
  Vec3 origin = Vec3::Zero();   ///< orthographic: the look-at centre; perspective: the eye
  bool perspective = false;
  double scale = 1;             ///< pixels per model unit (orthographic) or per unit of tan(angle) (perspective)
  Vec2 offset = Vec2::Zero();   ///< pixel position of the view axis

  /// Pixel x, pixel y and a nearness key of model point p. The key grows towards the viewer and
  /// is affine in pixel coordinates across a triangle, so it can be interpolated linearly.
  Vec3 project(const Vec3& p) const;
  /// Distance (model units) of a key along the view axis; orthographic distances are relative
  /// to the look-at plane, so only differences are meaningful.
  double distance(double key) const;
  /// Model units that one pixel covers at a key's depth.
  double pixel_size(double key) const;
  /// Unit vector from model point p towards the viewer.
  Vec3 to_viewer(const Vec3& p) const;
};

/// A camera looking at the centre of `box` from the setup's direction, with unit scale and
/// zero offset (so project() gives frame-independent screen coordinates, y down).
/// Throws InputError for a zero or non-finite up axis or an out-of-range field of view.
Camera aim_camera(const BoundingBox& box, const CameraSetup& setup);

/// Scales and shifts an aimed camera so that the screen rectangle [low, high] (in the aimed
/// camera's unit coordinates) is centred in a width x height pixel frame and fills it up to
/// the margin. A zero-size rectangle keeps unit scale; an empty one (low > high) also puts the
/// view axis at the frame's centre.
void frame_camera(Camera& camera, const Vec2& low, const Vec2& high, int width, int height, double margin_fraction);

}  // namespace dg
