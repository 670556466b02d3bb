#pragma once
// Writing output files so that a failed run never leaves a half-written file behind.

#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>

namespace dg {

/// The file standing where `folder` or one of its parents should be a folder (so that folder
/// cannot be made), or nothing.
std::optional<std::filesystem::path> file_in_the_way(const std::filesystem::path& folder);

/// Writes a file by streaming into `path` + ".tmp-<pid>" and renaming it into place.
/// `binary` opens the stream in binary mode. Throws InputError when the folder is not writable,
/// saying why: the folder is missing, a file is in its way, or the system's reason.
void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write,
                           bool binary = true);

}  // namespace dg
