#pragma once
// Ground truth for one repetition of a model: the rigid transform that maps repeated unit k
// onto unit k+1, how many units there are, and what one unit measures on the mesh.

#include "geometry/mesh.h"

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

namespace dg::assets {

/// Which points belong to one representative unit (tested on vertices and triangle centroids).
using Region = std::function<bool(const Vec3&)>;

/// Size of one unit on a mesh.
struct UnitMeasure {
  double area = 0.0;           ///< total area of triangles whose centroid lies in the region (m^2)
  std::size_t vertices = 0;    ///< vertices (referenced by a triangle) inside the region
};

/// One repetition: `transform` maps unit k onto unit k+1 for k = 0 .. count-2.
struct Repetition {
  std::string name;        ///< e.g. "columns"
  std::string kind;        ///< "translation", "rotation" or "screw"
  Mat4 transform = Mat4::Identity();
  nlohmann::json pitch;    ///< translation: {"vector"}; rotation: {"angle_deg","axis","point"}; screw: + "rise"
  int count = 0;           ///< number of repeated units (what a resize changes)
  std::string unit;        ///< plain-words definition of one unit and of `count`
  UnitMeasure measure;     ///< unit 0 measured on the generated mesh
};

/// Half-open box region lo <= p < hi (per coordinate).
Region box_region(const Vec3& lo, const Vec3& hi);
/// Area and vertex count of the part of `mesh` inside `region`.
UnitMeasure measure_unit(const TriangleMesh& mesh, const Region& region);

/// Translation by v (model units).
Mat4 translation_matrix(const Vec3& v);
/// Rotation by `angle` radians about the z axis through the origin, then a lift by `rise` along z.
Mat4 screw_matrix_z(double angle, double rise);

/// A translation repetition by `pitch`.
Repetition translation_repetition(std::string name, const Vec3& pitch, int count, std::string unit);
/// A rotation by `degrees` about +z through the origin.
Repetition rotation_repetition(std::string name, double degrees, int count, std::string unit);
/// A screw motion: rotation by `degrees` about +z and a rise along +z (model units).
Repetition screw_repetition(std::string name, double degrees, double rise, int count, std::string unit);

/// JSON of a 4x4 matrix: four rows of four numbers (row-major).
nlohmann::json matrix_json(const Mat4& m);
/// JSON record of a repetition (all fields; transform as matrix_json).
nlohmann::json to_json(const Repetition& repetition);

}  // namespace dg::assets
