#pragma once
// The guided-growth scene file (JSON, documented in docs/scene-file.md): L-systems (inline
// text in the L-system syntax, or a path), guides with polygons and seeds, links with tokens,
// spring settings, edits and limits.

#include "synthesis/growth_scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace dg {

/// Reads a scene. L-system paths are relative to the scene file's folder. Throws InputError
/// "FILE: where: problem" (e.g. "palm.json: links[2]: unknown guide 'top'"); a JSON syntax
/// error names the line and column.
GrowthScene read_growth_scene(const std::filesystem::path& path);

/// Parses a scene from JSON text; `source` names it in messages, `folder` resolves L-system paths.
GrowthScene parse_growth_scene(const std::string& text, const std::string& source, const std::filesystem::path& folder);

/// Reads an edits file: a JSON array of edit operations (or an object with an "edits" array)
/// whose guide names refer to `scene`.
std::vector<GuideEdit> read_guide_edits(const std::filesystem::path& path, const GrowthScene& scene);

}  // namespace dg
