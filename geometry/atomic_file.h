#pragma once
// Writing output files so that a failed run never leaves a half-written file behind.

#include <filesystem>
#include <functional>
#include <ostream>

namespace dg {

/// Writes a file by streaming into `path` + ".tmp-<pid>" and renaming it into place.
/// `binary` opens the stream in binary mode. Throws InputError when the folder is not writable.
void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write,
                           bool binary = true);

}  // namespace dg
