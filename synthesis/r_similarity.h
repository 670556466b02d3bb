#pragma once
// An estimate of r-similarity (paper 001 §3.1): the fraction of sampled candidate points y
// whose r-neighbourhood matches an r-neighbourhood of the exemplar under a rigid motion.
//
// Method. Both surfaces get dense area-uniform samples (spacing `spacing_r` * r) with normals;
// the r-neighbourhood of a point is intrinsic, as in the paper: the dense samples on the part of
// the surface inside the Euclidean ball of radius r that is connected to the point within the
// ball (so a close but separate part, e.g. a stake beside a post, is not in it).
// A motion T (candidate -> exemplar) matches at y when every candidate sample of the ball
// around y, mapped by T, lies within `tolerance` of an exemplar triangle whose normal agrees
// within `normal_tolerance_degrees`, and every exemplar sample of the ball around T(y), mapped
// back, lies as close to a candidate triangle (distances to the exact triangles, both ways).
// Motions are proposed, for each test point y, in this order:
//  1. motions that matched earlier test points (the identity first), most used first;
//  2. frame-to-frame alignments of the candidate's feature-line ends (keypoints) near y with
//     every exemplar keypoint of the same kind and dihedral angle, then of feature-line samples
//     near y (both tangent directions) with compatible exemplar feature samples;
//  3. for a flat ball, the alignment with a flat full disk of the exemplar (found among up to
//     1024 exemplar dense samples).
// Proposals of steps 2 and 3 must first bring 8 spread-out samples of the ball, then all of it,
// within the tolerance of the exemplar (exact frames: corners, straight edges, flat disks); then
// point-to-plane ICP refines them before the test (at most `max_alignments` per test point).
// When none matches, step 2 runs again accepting proposals within twice the tolerance (curved
// feature lines, whose sampled frames are only close), at most `max_loose_alignments` of them.
// Exemplar anchors of equal dihedral are tried in a fixed pseudo-random order. Test points run in
// batches of `batch_size`: in parallel within a batch, with the motions found by earlier
// batches; at the end failed points retry every motion found. So the result is deterministic
// for any thread count. Smooth curved neighbourhoods without feature lines within r are matched
// only through step 1 (motions found at feature points of the same piece) or step 3.
//
// Point clouds. A cloud stands in for its surface as disks (splats) in the points' tangent
// planes, of radius twice the median distance to the 4th nearest point (at most eps), so the
// disks cover the gaps between points; distances are taken to those disks, whatever their
// normals (a cloud's normals, fitted or scanned, blur at creases; normal_tolerance_degrees is
// for meshes); the connected part of a ball links points whose disks overlap; the dense samples
// are the points thinned to the first in each cube of edge spacing_r * r; test points are points
// picked at random. The keypoints of step 2 are the cloud's corners (cloud_keypoints), its
// feature samples points along its creases (cloud_crease_samples), and twice `anchors` of them
// are tried (their frames are fitted to noisy points). Up to 2 % of a ball's samples may miss
// the other surface (random gaps at edges and corners), and the distance tolerance widens to
// 3.5 x the two clouds' combined noise (point_statistics) when that is larger, up to eps.

#include "geometry/feature_lines.h"
#include "geometry/mesh.h"
#include "geometry/progress.h"
#include "symmetry/candidates.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace dg {

struct RSimilarityOptions {
  std::size_t samples = 1000;            ///< test points on the candidate (area-uniform)
  std::uint64_t seed = 1;                ///< seeds test points and dense samples
  double spacing_r = 0.2;                ///< dense sample spacing as a fraction of r
  double tolerance_eps = 0.25;           ///< distance tolerance as a fraction of eps = r/4 (at most 1)
  double normal_tolerance_degrees = 10.0;
  double dihedral_tolerance_degrees = 5.0;  ///< feature points pair only when their dihedral angles agree
  int icp_iterations = 10;
  std::size_t anchors = 2;         ///< nearest candidate keypoints (and feature samples) tried per test point
  std::size_t max_alignments = 32;       ///< ICP + test attempts per test point for exact proposals
  std::size_t max_loose_alignments = 16; ///< ... and for proposals only within 2 x tolerance
  std::size_t batch_size = 64;
  std::size_t max_motions = 512;   ///< motions kept for reuse
};

struct RSimilarityResult {
  double r = 0.0;          ///< model units
  double tolerance = 0.0;  ///< model units
  std::size_t samples = 0;
  std::size_t similar = 0;
  double fraction = 0.0;                ///< similar / samples (1 when there are no samples)
  std::vector<Vec3> dissimilar_points;  ///< test points without a match, in sampling order
  std::size_t motions = 0;              ///< distinct motions kept for reuse
  std::size_t searched = 0;             ///< test points that needed a search (step 2 or 3)
  std::size_t dense_samples_exemplar = 0, dense_samples_candidate = 0;
};

/// One side of the comparison: a welded mesh with its feature lines (extract_feature_lines at
/// spacing eps = r/4), or a point cloud with unit normals with its corners and crease samples
/// (cloud_keypoints and cloud_crease_samples of its voxel surface at eps).
struct SimilarityInput {
  const TriangleMesh* mesh = nullptr;
  const FeatureLines* feature_lines = nullptr;  ///< with mesh
  const PointCloud* cloud = nullptr;
  std::span<const Keypoint> cloud_keypoints;   ///< with cloud
  std::span<const Keypoint> cloud_creases;     ///< with cloud: cloud_crease_samples
};

/// Estimates how r-similar `candidate` is to `exemplar` for radius r (model units): two meshes or
/// two point clouds. Throws InputError when a side has no triangles (no points), a cloud has no
/// normals, or r is not positive.
RSimilarityResult estimate_r_similarity(const SimilarityInput& exemplar, const SimilarityInput& candidate, double r,
                                        const RSimilarityOptions& options = {}, const ProgressCallback& progress = {});

}  // namespace dg
