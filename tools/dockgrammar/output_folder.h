#pragma once
// The folder a command writes its files into.

#include <filesystem>

namespace dg::cli {

/// Creates `folder` and its missing parents (nothing for an empty path, the current folder);
/// throws InputError "FOLDER: cannot create the output folder: REASON" when that fails (a file in
/// the way is named).
void create_output_folder(const std::filesystem::path& folder);

}  // namespace dg::cli
