#pragma once
// Where the third-party test corpus lives: ../shared/corpus next to the source tree. Tests that
// need it skip with a WARN when the file is absent.

#include <catch2/catch.hpp>

#include <filesystem>
#include <optional>
#include <string>

namespace dg::test {

/// The corpus file `relative`, e.g. "meshes/arch-sh3d-railing/railing.obj" (may not exist).
inline std::filesystem::path corpus_file(const std::string& relative) {
  return std::filesystem::path(DOCKGRAMMAR_SOURCE_DIR) / ".." / "shared" / "corpus" / relative;
}

/// The corpus file `relative` when it exists; otherwise nothing, after a WARN naming the missing
/// path, so the calling test returns and its corpus check is reported as skipped.
inline std::optional<std::filesystem::path> corpus_file_if_present(const std::string& relative) {
  std::filesystem::path path = corpus_file(relative);
  if (std::filesystem::exists(path)) return path;
  WARN("corpus not found at " << path.string() << ": corpus check skipped");
  return std::nullopt;
}

}  // namespace dg::test
