#include "assets/generator/repetition.h"

#include <cmath>
#include <numbers>
#include <vector>

namespace dg::assets {

Region box_region(const Vec3& lo, const Vec3& hi) {
  return [lo, hi](const Vec3& p) {
    return (p.array() >= lo.array()).all() && (p.array() < hi.array()).all();
  };
}

UnitMeasure measure_unit(const TriangleMesh& mesh, const Region& region) {
  UnitMeasure measure;
  std::vector<char> used(mesh.positions.size(), 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    if (region((a + b + c) / 3.0)) measure.area += 0.5 * mesh.area_vector(t).norm();
    for (std::uint32_t v : mesh.triangles[t]) used[v] = 1;
  }
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    if (used[v] && region(mesh.positions[v])) ++measure.vertices;
  }
  return measure;
}

Mat4 translation_matrix(const Vec3& v) {
  Mat4 m = Mat4::Identity();
  m.block<3, 1>(0, 3) = v;
  return m;
}

Mat4 screw_matrix_z(double angle, double rise) {
  Mat4 m = Mat4::Identity();
  m(0, 0) = std::cos(angle);
  m(0, 1) = -std::sin(angle);
  m(1, 0) = std::sin(angle);
  m(1, 1) = std::cos(angle);
  m(2, 3) = rise;
  return m;
}

Repetition translation_repetition(std::string name, const Vec3& pitch, int count, std::string unit) {
  Repetition r;
  r.name = std::move(name);
  r.kind = "translation";
  r.transform = translation_matrix(pitch);
  r.pitch = {{"vector", {pitch.x(), pitch.y(), pitch.z()}}};
  r.count = count;
  r.unit = std::move(unit);
  return r;
}

Repetition rotation_repetition(std::string name, double degrees, int count, std::string unit) {
  Repetition r;
  r.name = std::move(name);
  r.kind = "rotation";
  r.transform = screw_matrix_z(degrees * std::numbers::pi / 180.0, 0.0);
  r.pitch = {{"angle_deg", degrees}, {"axis", {0.0, 0.0, 1.0}}, {"point", {0.0, 0.0, 0.0}}};
  r.count = count;
  r.unit = std::move(unit);
  return r;
}

Repetition screw_repetition(std::string name, double degrees, double rise, int count, std::string unit) {
  Repetition r = rotation_repetition(std::move(name), degrees, count, std::move(unit));
  r.kind = "screw";
  r.transform(2, 3) = rise;
  r.pitch["rise"] = rise;
  return r;
}

nlohmann::json matrix_json(const Mat4& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < 4; ++i) rows.push_back({m(i, 0), m(i, 1), m(i, 2), m(i, 3)});
  return rows;
}

nlohmann::json to_json(const Repetition& repetition) {
  return {{"name", repetition.name},
          {"kind", repetition.kind},
          {"transform", matrix_json(repetition.transform)},
          {"pitch", repetition.pitch},
          {"count", repetition.count},
          {"unit", repetition.unit},
          {"unit_area", repetition.measure.area},
          {"unit_vertices", repetition.measure.vertices}};
}

}  // namespace dg::assets
