#include "tools/dockgrammar/output_folder.h"

#include "geometry/errors.h"

namespace dg::cli {

void create_output_folder(const std::filesystem::path& folder) {
  if (folder.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw InputError(folder.string() + ": cannot create the output folder");
}

}  // namespace dg::cli
