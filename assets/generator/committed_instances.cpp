#include "assets/generator/committed_instances.h"

#include "geometry/atomic_file.h"
#include "geometry/model_io.h"
#include "geometry/submesh.h"
#include "geometry/surface_sampling.h"

namespace dg::assets {

std::vector<Instance> committed_instances() {
  return {{"fence_4", "fence", {{"n", 4}}},
          {"fence_9", "fence", {{"n", 9}}},
          {"facade_3x4", "facade", {{"columns", 3}, {"rows", 4}}},
          {"facade_5x7", "facade", {{"columns", 5}, {"rows", 7}}},
          {"spiral_stairs_12", "spiral_stairs", {{"steps", 12}}},
          {"gear_12", "gear", {{"teeth", 12}}},
          {"shelf_3x4", "shelf", {{"columns", 3}, {"rows", 4}}},
          {"pipe_tree_3", "pipe_tree", {{"depth", 3}}},
          {"messy_facade_3x4", "messy_facade", {{"columns", 3}, {"rows", 4}}}};
}

std::filesystem::path ground_truth_path(const std::filesystem::path& mesh_path) {
  std::filesystem::path path = mesh_path;
  return path.replace_extension(".json");
}

void write_asset_files(const Asset& asset, const std::filesystem::path& mesh_path) {
  nlohmann::json truth = asset.ground_truth;
  if (lower_extension(mesh_path) == ".glb") {
    // glTF's up axis is +y: the generator's up axis +z is turned onto it (and +y onto -z).
    RigidTransform z_up_to_y_up;
    z_up_to_y_up.rotation << 1, 0, 0, 0, 0, 1, 0, -1, 0;
    write_mesh(mesh_path, transformed(asset.mesh, z_up_to_y_up));
    truth["file_frame"] =
        "the .glb holds the model turned so that its up axis z is glTF's +y: a point (x, y, z) of the values here lies "
        "at (x, z, -y) in the file";
  } else {
    write_mesh(mesh_path, asset.mesh);
  }
  const std::string text = truth.dump(2) + "\n";
  write_file_atomically(ground_truth_path(mesh_path), [&](std::ostream& out) { out << text; }, false);
}

void write_asset_points(const Asset& asset, const std::filesystem::path& ply_path, std::size_t count, std::uint64_t seed,
                        double noise) {
  PointCloud cloud = sample_surface(asset.mesh, count, seed);
  if (noise > 0.0) add_noise(cloud, noise, seed + 1);
  write_point_cloud(ply_path, cloud);
  nlohmann::json truth = asset.ground_truth;
  truth["sampled_points"] = {{"count", count}, {"seed", seed}, {"noise", noise}};
  const std::string text = truth.dump(2) + "\n";
  write_file_atomically(ground_truth_path(ply_path), [&](std::ostream& out) { out << text; }, false);
}

}  // namespace dg::assets
