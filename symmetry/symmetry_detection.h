#pragma once
// Partial symmetry detection (paper 001 §4.1): candidates from feature lines, verified on the
// voxel surface by exact geometry, eroded to r-symmetry, grouped into repetition families.

#include "geometry/prepared_model.h"
#include "symmetry/candidates.h"
#include "symmetry/families.h"
#include "symmetry/symmetric_region.h"

#include <string>
#include <vector>

namespace dg {

struct SymmetryOptions {
  CandidateOptions candidates;  ///< eps is taken from the voxel surface
  RegionOptions region;
  std::size_t max_verified = 80;             ///< candidates verified on the voxel surface, best supported first
  double min_r_symmetric_fraction = 0.005;   ///< smaller r-symmetric areas are dropped
  std::size_t max_seeds = 64;                ///< seed cells per candidate for region growing
  int max_power = 64;                        ///< highest generator power probed for families
  std::size_t max_keypoints = 20000;         ///< feature-line ends used (evenly thinned beyond)
  /// Point clouds: their corners' frames tilt and their positions scatter with the noise, so
  /// pair motions turning less than this vote as translations, keypoint matches reach this many
  /// times farther and dihedrals may differ this much (the motions are refined on the points after).
  double cloud_snap_to_translation_degrees = 10.0;
  double cloud_match_radius_scale = 4.0;
  double cloud_dihedral_tolerance_degrees = 15.0;
};

struct DetectedSymmetry {
  RigidTransform transform;  ///< canonical form (see canonical_motion)
  std::string kind;          ///< "translation", "rotation" or "screw"
  ScrewParameters screw;
  std::size_t support = 0;  ///< keypoint pairs it maps onto each other
  SymmetricRegion region;
  double symmetric_fraction = 0.0;    ///< of the model's surface
  double r_symmetric_fraction = 0.0;
  double symmetric_area = 0.0;        ///< model units^2 (scaled to the mesh's true area)
  double r_symmetric_area = 0.0;
  /// Share of the surface in xi_r(T) that T pins in place (see pinned_area); below
  /// min_r_symmetric_fraction the motion only slides parts along themselves and is no repeat.
  double pinned_fraction = 0.0;
  std::size_t family = 0;  ///< index into SymmetryResult::families
  int power = 1;           ///< this motion = family generator ^ power (up to inversion)
};

struct SymmetryStats {
  std::size_t keypoints = 0;
  std::size_t pair_transforms = 0;
  std::size_t candidates = 0;       ///< distinct refined candidates
  std::size_t verified = 0;         ///< candidates whose region was computed
  std::size_t unverified = 0;       ///< candidates beyond SymmetryOptions::max_verified, never verified
  std::size_t rejected_early = 0;   ///< dropped by the seed test before growing
  std::size_t rejected_small = 0;   ///< r-symmetric area below the minimum
  double seconds_per_verified = 0.0;
};

struct SymmetryResult {
  std::vector<DetectedSymmetry> symmetries;  ///< by r-symmetric area, largest first
  std::vector<SymmetryFamily> families;      ///< members index into symmetries
  SymmetryStats stats;
  std::vector<StageTiming> timings;
  std::string note;  ///< why nothing was found, when nothing was (e.g. no feature lines)
  /// The cell-matching tolerances the regions were computed with; later stages that test cells
  /// for these motions (docking sites, parts kept whole, pictures) match with the same.
  RegionOptions region;
};

/// Detects partial rigid symmetries of a prepared model. Deterministic for any thread count.
SymmetryResult detect_symmetries(const PreparedModel& prepared, const SymmetryOptions& options = {},
                                 const ProgressCallback& progress = {});

}  // namespace dg
