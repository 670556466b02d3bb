#pragma once
// Elementary docking sites and dockers (paper 001 §3.2–3.3), computed on the voxel surface.
//
// For a motion T with r-symmetric cells S = xi_r(T), every connected non-symmetric region is a
// docker candidate D. Its docking site is the band of S cells around it (two cell layers, so
// that the band's image under T still closes; the image is every cell the moved band covers,
// found from both sides, so it closes for motions that do not carry the voxel grid onto
// itself). The site is valid when its image T(site) also
// splits the model: the secondary docker D' is what T(site) encloses, i.e. every part of the
// model cut off by T(site) that holds no image of the geometry just outside the site. When
// T(site) does not split the model, neighbouring non-symmetric regions are added to the docker
// (the dependent pieces of the paper's Figure 5) until it does, or the candidate is dropped.
// The operation replaces D' by T(D): insert when D' lies inside D, delete when D lies inside D',
// replace otherwise, also when each lies inside the other (the same piece, nothing grows). Both T and T^-1 of every examined symmetry are used, which gives the
// paper's secondary operations as primary operations of the inverse.

#include "geometry/prepared_model.h"
#include "geometry/progress.h"
#include "geometry/rigid_transform.h"
#include "symmetry/symmetry_detection.h"

#include <cstdint>
#include <string>
#include <vector>

namespace dg {

enum class OperationKind { insert, remove, replace };

/// "insert", "delete" or "replace".
std::string operation_name(OperationKind kind);

struct DockingSiteOptions {
  /// Symmetries examined, largest r-symmetric area first, one per repetition family (its
  /// smallest power found): powers of a generator (2t, 3t, ...) only repeat its operations.
  std::size_t max_symmetries = 24;
  double containment = 0.9;         ///< share of cells that makes one docker "inside" another
  int max_merge_rounds = 4;         ///< dependent-region merges tried before giving up
  /// Sites whose band slides in this many independent rigid motions or more are slippable
  /// (3: the band lies on a plane or sphere, like a window frame on a flat wall).
  std::size_t slippable_dimension = 3;
};

struct DockingSite {
  std::size_t symmetry = 0;   ///< index into SymmetryResult::symmetries
  bool inverse = false;       ///< the operation uses the inverse of that symmetry's motion
  RigidTransform transform;   ///< T: maps the site onto the secondary site
  std::vector<std::uint32_t> site;              ///< band cells, ascending
  std::vector<std::uint32_t> docker;            ///< D, ascending
  std::vector<std::uint32_t> secondary_site;    ///< cells of T(site), ascending
  std::vector<std::uint32_t> secondary_docker;  ///< D', ascending
  std::size_t regions = 1;  ///< non-symmetric regions combined into the docker
  OperationKind operation = OperationKind::replace;
  /// T(D) would overlap geometry that stays in place (away from the seam): the operation is
  /// marked; synthesis re-checks placed pieces exactly.
  bool collides = false;
  /// A connected part of T(site) borders no cell of D': the secondary site also runs where
  /// nothing is cut off, so it is not the seam of D' alone.
  bool stray_seam = false;
  std::size_t slippable_motions = 0;  ///< slippage dimension of the band
  bool slippable = false;
  double docker_area = 0.0;            ///< model units^2
  double secondary_docker_area = 0.0;  ///< model units^2
};

struct DockingSiteStats {
  std::size_t motions = 0;             ///< motions examined (each symmetry in both directions)
  /// Symmetries that could give docking sites (one per repetition family) beyond
  /// DockingSiteOptions::max_symmetries, not examined.
  std::size_t symmetries_skipped = 0;
  std::size_t regions = 0;             ///< non-symmetric regions seen over all motions
  std::size_t invalid = 0;             ///< regions whose site image never split the model
};

struct DockingSiteResult {
  std::vector<DockingSite> sites;
  DockingSiteStats stats;
};

/// Elementary docking sites of the top symmetries of a prepared mesh or point cloud. Parallel over motions
/// (TBB) and deterministic for any thread count. `progress` hears stage "docking sites" with
/// the fraction of motions done, between batches of motions.
DockingSiteResult find_docking_sites(const PreparedModel& prepared, const SymmetryResult& symmetries,
                                     const DockingSiteOptions& options = {}, const ProgressCallback& progress = {});

}  // namespace dg
