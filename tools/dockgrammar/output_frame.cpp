#include "tools/dockgrammar/output_frame.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cctype>
#include <string>

namespace dg::cli {

RigidTransform file_frame(const std::filesystem::path& path, const Vec3& up) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  RigidTransform frame;
  if (extension == ".glb") frame.rotation = Eigen::Quaterniond::FromTwoVectors(up, Vec3::UnitY()).toRotationMatrix();
  return frame;
}

}  // namespace dg::cli
