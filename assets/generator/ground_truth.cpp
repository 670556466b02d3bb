#include "assets/generator/ground_truth.h"

namespace dg::assets {

nlohmann::json mesh_statistics(const TriangleMesh& mesh) {
  const BoundingBox box = mesh.bounds();
  return {{"triangle_count", mesh.triangles.size()},
          {"vertex_count", mesh.positions.size()},
          {"surface_area", mesh.area()},
          {"bounding_box",
           {{"min", {box.min.x(), box.min.y(), box.min.z()}}, {"max", {box.max.x(), box.max.y(), box.max.z()}}}}};
}

nlohmann::json grid_json(const Repetition& first, const Repetition& second, const UnitMeasure& cell, const std::string& cell_text) {
  return {{"repetitions", {first.name, second.name}},
          {"counts", {first.count, second.count}},
          {"cell", cell_text},
          {"cell_area", cell.area},
          {"cell_vertices", cell.vertices}};
}

Asset finish_asset(const std::string& name, const Parameters& parameters, TriangleMesh mesh,
                   const std::vector<Repetition>& repetitions, const nlohmann::json& grids,
                   const nlohmann::json& notes) {
  // Every generator builds its model standing on the xy plane: z is up.
  nlohmann::json truth = {{"name", name}, {"generator", parameters.model}, {"parameters", parameters.used}, {"units", "m"}, {"up", "z"}};
  truth.update(mesh_statistics(mesh));
  truth["repetitions"] = nlohmann::json::array();
  for (const Repetition& r : repetitions) truth["repetitions"].push_back(to_json(r));
  truth["grids"] = grids.is_null() ? nlohmann::json::array() : grids;
  truth.update(notes);
  return Asset{name, std::move(mesh), std::move(truth)};
}

}  // namespace dg::assets
