#pragma once
// The folder a command writes its files into.

#include <filesystem>

namespace dg::cli {

/// Creates `folder` and its missing parents (nothing for an empty path, the current folder);
/// throws InputError "FOLDER: cannot create the output folder" when that fails.
void create_output_folder(const std::filesystem::path& folder);

}  // namespace dg::cli
