#include "tools/dockgrammar/output_frame.h"

#include "geometry/model_io.h"

#include <Eigen/Geometry>

namespace dg::cli {

RigidTransform file_frame(const std::filesystem::path& path, const Vec3& up) {
  RigidTransform frame;
  if (lower_extension(path) == ".glb") frame.rotation = Eigen::Quaterniond::FromTwoVectors(up, Vec3::UnitY()).toRotationMatrix();
  return frame;
}

}  // namespace dg::cli
