#include "tools/dockgrammar/pictures.h"

#include <array>

namespace dg::cli {

MeshRenderOptions picture_options(const TriangleMesh& mesh) {
  MeshRenderOptions options;
  const Vec3 size = mesh.bounds().size();
  if (size.y() < size.x() && size.y() < size.z()) options.camera.up = Vec3(0, 0, 1);
  return options;
}

Rgba8 class_color(std::size_t i) {
  static constexpr std::array<Rgba8, 10> palette{{{228, 26, 28, 255},
                                                  {55, 126, 184, 255},
                                                  {77, 175, 74, 255},
                                                  {152, 78, 163, 255},
                                                  {255, 127, 0, 255},
                                                  {230, 200, 40, 255},
                                                  {166, 86, 40, 255},
                                                  {247, 129, 191, 255},
                                                  {100, 100, 100, 255},
                                                  {27, 158, 119, 255}}};
  return palette[i % palette.size()];
}

}  // namespace dg::cli
