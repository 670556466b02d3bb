#pragma once
// Where the third-party test corpus lives: ../shared/corpus next to the source tree. Tests that
// need it skip with a WARN when the file is absent.

#include <filesystem>
#include <string>

namespace dg::test {

/// The corpus file `relative`, e.g. "meshes/arch-sh3d-railing/railing.obj" (may not exist).
inline std::filesystem::path corpus_file(const std::string& relative) {
  return std::filesystem::path(DOCKGRAMMAR_SOURCE_DIR) / ".." / "shared" / "corpus" / relative;
}

}  // namespace dg::test
