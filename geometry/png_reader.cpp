#include "geometry/png_reader.h"

#include "geometry/errors.h"

#include <png.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace dg {

Image read_png(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot read");
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < 8 || png_sig_cmp(bytes.data(), 0, 8) != 0) throw InputError(path.string() + ": not a PNG file");
  png_image info{};
  info.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&info, bytes.data(), bytes.size()))
    throw InputError(path.string() + ": malformed PNG (" + info.message + ")");
  if (info.width == 0 || info.height == 0 || static_cast<double>(info.width) * info.height > double(1 << 28)) {
    png_image_free(&info);
    throw InputError(path.string() + ": PNG size " + std::to_string(info.width) + "x" + std::to_string(info.height) + " is not supported");
  }
  info.format = PNG_FORMAT_RGBA;
  Image image(static_cast<int>(info.width), static_cast<int>(info.height), Rgba8{255, 255, 255, 255});
  if (!png_image_finish_read(&info, nullptr, image.pixels.data(), static_cast<png_int_32>(info.width * 4), nullptr))
    throw InputError(path.string() + ": malformed PNG (" + info.message + ")");
  return image;
}

}  // namespace dg
