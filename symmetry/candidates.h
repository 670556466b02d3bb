#pragma once
// Candidate rigid transforms from feature lines (paper 001 §4.1): pairs of compatible
// keypoints (feature-line ends with a frame) give frame-to-frame motions; the motions are
// voted in transformation space and each peak is refined on the keypoints (ICP + Kabsch).

#include "geometry/feature_lines.h"
#include "geometry/rigid_transform.h"

#include <cstdint>
#include <vector>

namespace dg {

/// A feature-line end: position with an orthonormal frame whose tangent points into the line.
struct Keypoint {
  Vec3 position, tangent, normal, binormal;
  FeatureDescriptor descriptor;
};

/// Ends of all open feature lines (two per line), in line order.
std::vector<Keypoint> feature_keypoints(const FeatureLines& lines);

/// For a mesh whose feature lines are all closed loops (rings of tori, rims of cylinders: no
/// ends to align): keypoints at every vertex of every closed line of `mesh`, two per vertex, the
/// tangent along the edge to the next vertex and along the edge to the previous one (a motion
/// may map a loop onto another traversed the other way); normal and descriptor as the samples
/// of that edge have them. Empty when there is no closed line.
std::vector<Keypoint> loop_keypoints(const FeatureLines& lines, const TriangleMesh& mesh);

struct CandidateOptions {
  double eps = 0.0;                     ///< voxel size, model units (required)
  double dihedral_tolerance_degrees = 5.0;
  std::size_t max_sources = 600;        ///< keypoints used as sources (evenly strided)
  std::size_t max_pairs = 3'000'000;    ///< budget of voted pairs; fewer sources are used beyond it
  std::size_t min_support = 3;          ///< matched keypoint pairs a candidate needs after refinement
  double angle_bin_radians = 0.035;     ///< voting bin for the rotation vector
  double translation_bin_eps = 2.0;     ///< voting bin for the centre's displacement, in eps
  /// Pair motions turning by less than this (radians) vote as the translation between the two
  /// keypoints: the frames of a noisy point cloud's corners tilt by a few degrees, which would
  /// move the displacement of a far centre by many voxels. 0 = off (exact frames of meshes).
  double snap_to_translation_radians = 0.0;
  /// Keypoint ICP match radii (1, 0.25, 0.1 eps) are multiplied by this (noisy corners).
  double match_radius_scale = 1.0;
};

/// A proposed symmetry with its support: keypoint index pairs (source, image) that it maps
/// onto each other within tolerance.
struct Candidate {
  RigidTransform transform;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> matches;
};

struct CandidateStats {
  std::size_t keypoints = 0;
  std::size_t pair_transforms = 0;  ///< frame-to-frame motions voted
  std::size_t peaks = 0;            ///< vote peaks examined
  std::size_t candidates = 0;       ///< distinct refined candidates returned
};

/// Candidates sorted by support (descending), identity and inverse duplicates removed (each
/// returned motion is in canonical form, see canonical_motion). `centre` is the point whose
/// displacement is binned (use the bounding-box centre). Deterministic.
std::vector<Candidate> find_candidates(const std::vector<Keypoint>& keypoints, const Vec3& centre,
                                       const CandidateOptions& options, CandidateStats* stats = nullptr);

/// Refines a given motion on the keypoints (the same ICP as find_candidates) and returns it in
/// canonical form with its keypoint matches; used to probe powers of a family's generator.
Candidate refine_candidate(const RigidTransform& transform, const std::vector<Keypoint>& keypoints,
                           const CandidateOptions& options);

/// T or its inverse, whichever is canonical: with the screw axis oriented to have a positive
/// component along the first axis where it is clearly non-zero (above 1e-3 of its length, so
/// that fitting noise on a motion along an axis does not choose), translations and screws keep a positive
/// slide and rotations an angle in (0, pi]. T and T^-1 give the same canonical motion.
RigidTransform canonical_motion(const RigidTransform& transform, double slide_tolerance);

}  // namespace dg
