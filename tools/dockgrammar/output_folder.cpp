#include "tools/dockgrammar/output_folder.h"

#include "geometry/errors.h"

namespace dg::cli {

void create_output_folder(const std::filesystem::path& folder) {
  if (folder.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (!error) return;
  // Name what is in the way: a file where the folder (or one of its parents) should be, or the
  // system's reason (permissions, a read-only disk).
  for (std::filesystem::path part = folder; !part.empty() && part != part.parent_path(); part = part.parent_path()) {
    std::error_code ignored;
    if (std::filesystem::exists(part, ignored) && !std::filesystem::is_directory(part, ignored))
      throw InputError(folder.string() + ": cannot create the output folder: " + part.string() +
                       " is a file, not a folder");
  }
  throw InputError(folder.string() + ": cannot create the output folder: " + error.message());
}

}  // namespace dg::cli
