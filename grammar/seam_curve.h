#pragma once
// The seam curve of a piece cut out of a mesh, and whether two seam curves coincide (so the
// piece cut at one location fits the hole left at another).

#include "geometry/mesh.h"
#include "geometry/rigid_transform.h"
#include "geometry/segment_index.h"
#include "geometry/topology.h"

#include <array>
#include <cstdint>
#include <numbers>
#include <optional>
#include <vector>

namespace dg {

/// How far apart (fraction of the voxel size eps) two seam curves may lie and still fit. Exact
/// repeats agree up to the float32 rounding of the source coordinates (the Kenney
/// building-small-c: up to 1e-5 eps). Real assets repeat less exactly, and their motions are
/// fitted to feature-line ends: from location to location, the seams of the Sweet Home 3D
/// railing, the table football, the chandelier and the zdm2 map lie 1e-4 to 1e-2 eps apart
/// (1e-4 eps kept 3 of their 39 non-terminals). Derived pieces are welded within twice the
/// largest misfit their grammar measured (seam_weld_tolerance, grammar/context_free.h), at
/// least kSeamWeldFloorFraction eps, so a grammar of exact repeats welds as tightly as before.
inline constexpr double kSeamFitFraction = 1e-2;

/// Smallest weld distance (fraction of eps) for the seams of derived pieces: float32 rounding.
inline constexpr double kSeamWeldFloorFraction = 1e-4;

/// Largest perimeter (fraction of eps) of a hole of three open edges that welding a seam may
/// leave and that is then closed (close_triangular_holes): the Sweet Home 3D railing resized to
/// no unit left one of 0.2 eps where a bar's seam vertex welded to the handrail's.
inline constexpr double kSeamHoleFraction = 0.5;

/// Edges between a flagged triangle (`inside`, one flag per triangle) and an unflagged one
/// (any of them, at an edge that more than two triangles use): the curve along which the flagged
/// piece was cut from the rest. Edges on the model's own border are not part of it.
std::vector<Segment> seam_segments(const TriangleMesh& mesh, const EdgeUsers& users,
                                   const std::vector<std::uint32_t>& piece, const std::vector<char>& inside);

/// How far apart two seam curves lie (model units): the largest distance from an end or
/// midpoint of a segment of either curve to the nearest segment of the other. Infinity when
/// some point has no segment of the other curve within `limit`. `cell` sizes the spatial hash
/// (about the segment length).
double seam_misfit(const std::vector<Segment>& a, const std::vector<Segment>& b, double limit, double cell);

/// How far (fraction of eps) a location's seam curve may lie from its class's first one and
/// still have its frame aligned onto it (align_seam_curve's reach): repeats a user placed by
/// hand sit up to 0.13 eps off the motion between them (the table football's rods).
inline constexpr double kSeamAlignReachFraction = 0.5;

/// How much (fraction) a seam curve's length may differ from the one it is aligned onto: a
/// rigid motion keeps lengths, and copies cut a little off their place differ by far less (the
/// table football's rod ends: not at all); curves of other lengths are other seams, not tried.
inline constexpr double kSeamAlignLengthFraction = 0.02;

/// Largest rotation (radians, 1 degree: the symmetry stage's default angle tolerance) by which
/// aligning a seam curve may turn a location's frame.
inline constexpr double kSeamAlignMaxAngle = std::numbers::pi / 180.0;

/// Rounds of align_seam_curve that pair segment ends with segment ends, then rounds that pair
/// samples with the nearest point of the other curve.
inline constexpr int kSeamAlignEndRounds = 2, kSeamAlignIterations = 8;

/// The rigid motion that carries curve `moving` onto curve `reference`, from the identity: least
/// squares over both curves' segment ends paired with the other's nearest segment end
/// (kSeamAlignEndRounds times, while every end has one within `reach`), then over their ends
/// and midpoints paired with the nearest point of the other curve (kSeamAlignIterations times).
/// Nothing when a sample has no point of the other curve within `reach` (model units) on the
/// way. `cell` sizes the spatial hash.
std::optional<RigidTransform> align_seam_curve(const std::vector<Segment>& moving, const std::vector<Segment>& reference,
                                               double reach, double cell);

}  // namespace dg
