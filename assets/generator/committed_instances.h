#pragma once
// The small model instances committed to assets/models/ and how they are written to disk
// (OBJ mesh + JSON ground truth side by side).

#include "assets/generator/asset.h"

#include <filesystem>
#include <string>
#include <vector>

namespace dg::assets {

/// One committed instance: file stem in assets/models/, model name and parameters.
struct Instance {
  std::string stem;
  std::string model;
  nlohmann::json params;
};

/// The instances `dockgrammar-assets --all` writes, in a fixed order.
std::vector<Instance> committed_instances();

/// Path of the ground-truth file of a mesh file: same folder and stem, extension ".json".
std::filesystem::path ground_truth_path(const std::filesystem::path& mesh_path);

/// Writes the mesh to `mesh_path` (format by extension, via write_mesh) and the ground truth
/// next to it, both atomically. A .glb is turned to glTF's y-up frame, (x, y, z) -> (x, z, -y),
/// and its ground truth (values in the generator's z-up frame) says so under "file_frame".
/// Throws InputError for an unwritable path or unknown format.
void write_asset_files(const Asset& asset, const std::filesystem::path& mesh_path);

/// Writes a scan-like point cloud of the asset to `ply_path` (`count` points drawn area-uniformly
/// on its surface with `seed`, with the triangles' normals, each moved by Gaussian noise of
/// standard deviation `noise` model units per axis; see sample_surface and add_noise) and the
/// ground truth next to it with "sampled_points": {"count", "seed", "noise"} added, both
/// atomically. Throws InputError unless the path ends in .ply or when it cannot be written.
void write_asset_points(const Asset& asset, const std::filesystem::path& ply_path, std::size_t count, std::uint64_t seed,
                        double noise);

}  // namespace dg::assets
