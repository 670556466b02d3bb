#include "geometry/atomic_file.h"

#include "geometry/errors.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>
#include <unistd.h>

namespace dg {
namespace {

// Why a file could not be opened for writing at `path`: a file stands where its folder should
// be, its folder is missing, else the system's reason (read right after the failed open).
std::string why_not_writable(const std::filesystem::path& path) {
  const int reason = errno;
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  if (const std::optional<std::filesystem::path> file = file_in_the_way(folder)) return file->string() + " is a file, not a folder";
  std::error_code ignored;
  if (!std::filesystem::exists(folder, ignored)) return "the folder " + folder.string() + " does not exist";
  return reason != 0 ? std::strerror(reason) : "unknown reason";
}

}  // namespace

std::optional<std::filesystem::path> file_in_the_way(const std::filesystem::path& folder) {
  for (std::filesystem::path part = folder; !part.empty() && part != part.parent_path(); part = part.parent_path()) {
    std::error_code ignored;
    if (std::filesystem::exists(part, ignored) && !std::filesystem::is_directory(part, ignored)) return part;
  }
  return std::nullopt;
}

void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write,
                           bool binary) {
  std::filesystem::path temporary = path;
  temporary += ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, binary ? std::ios::binary | std::ios::trunc : std::ios::trunc);
    if (!out) throw InputError(path.string() + ": cannot open for writing: " + why_not_writable(path));
    try {
      write(out);
    } catch (...) {
      out.close();
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw;
    }
    out.flush();
    if (!out) {
      out.close();
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw InputError(path.string() + ": write failed (disk full?)");
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    throw InputError(path.string() + ": cannot move the finished file into place");
  }
}

}  // namespace dg
