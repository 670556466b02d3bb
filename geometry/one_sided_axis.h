#pragma once
// A model's up axis read off the way its surface faces: a scan seen from above (a building from
// a drone or a street, a room from its ceiling) holds roofs, floors and table tops facing up and
// nothing facing down, since no sensor looked from below.

#include "geometry/model_io.h"

#include <optional>

namespace dg {

/// How a model's surface faces along one coordinate axis, as shares of its surface (area for a
/// mesh, points for a cloud): facing +axis, -axis (normals within kFacingDegrees of it) and
/// across it (normals within kFacingDegrees of perpendicular).
struct AxisFacing {
  int axis = 1;  ///< 0 = x, 1 = y, 2 = z
  double up = 0.0, down = 0.0, across = 0.0;
};

/// Normals within this angle (degrees) of +-axis face along it; within it of perpendicular, across.
inline constexpr double kFacingDegrees = 30.0;

/// The thresholds of one_sided_up_axis: at least kOneSidedUp of the surface faces +axis, at most
/// kOneSidedDown times that faces -axis, at least kOneSidedAcross faces across (walls: a flat
/// sheet facing one way is a facade or a terrain, not a scan of a standing thing), and the model
/// is no thinner along the axis than kOneSidedHeight of its smaller other extent (a facade
/// standing along the axis, seen from its front, faces +axis alone).
inline constexpr double kOneSidedUp = 0.05;
inline constexpr double kOneSidedDown = 0.02;
inline constexpr double kOneSidedAcross = 0.2;
inline constexpr double kOneSidedHeight = 0.35;

/// The coordinate axis a model was seen from above along: the only axis that meets the
/// thresholds above. Meshes are measured by triangle area (a closed mesh faces every way alike
/// and gives nothing), point clouds by their points' normals (nothing for a cloud without
/// normals: fitted normals carry no side). Nothing when no axis, or more than one, qualifies.
std::optional<AxisFacing> one_sided_up_axis(const Model& model);

}  // namespace dg
