#include "tools/dockgrammar/output_folder.h"

#include "geometry/atomic_file.h"
#include "geometry/errors.h"

namespace dg::cli {

void create_output_folder(const std::filesystem::path& folder) {
  if (folder.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (!error) return;
  // Name what is in the way, else the system's reason (permissions, a read-only disk).
  const std::optional<std::filesystem::path> file = file_in_the_way(folder);
  throw InputError(folder.string() + ": cannot create the output folder: " +
                   (file ? file->string() + " is a file, not a folder" : error.message()));
}

}  // namespace dg::cli
