#include "tests/grammar/inference_measure.h"

#include "grammar/derivation.h"
#include "synthesis/turtle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace dg::test {

namespace {

void densify(const std::vector<Vec2>& line, double spacing, std::vector<Vec2>& out) {
  if (line.size() == 1) out.push_back(line.front());
  for (std::size_t k = 1; k < line.size(); ++k) {
    const Vec2 a = line[k - 1], b = line[k];
    const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / spacing)));
    for (int j = 0; j < n; ++j) out.push_back(a + (b - a) * (static_cast<double>(j) / n));
    if (k + 1 == line.size()) out.push_back(b);
  }
}

double directed_hausdorff(const std::vector<Vec2>& from, const std::vector<Vec2>& to, double cell) {
  std::unordered_map<long long, std::vector<Vec2>> grid;
  auto key = [](long long x, long long y) { return x * 4000037LL + y; };
  for (const Vec2& p : to) grid[key(static_cast<long long>(std::floor(p.x() / cell)), static_cast<long long>(std::floor(p.y() / cell)))].push_back(p);
  double worst = 0;
  for (const Vec2& p : from) {
    const long long cx = static_cast<long long>(std::floor(p.x() / cell)), cy = static_cast<long long>(std::floor(p.y() / cell));
    double best = std::numeric_limits<double>::infinity();
    for (long long ring = 0; ring < 100000; ++ring) {
      for (long long x = cx - ring; x <= cx + ring; ++x)
        for (long long y = cy - ring; y <= cy + ring; ++y) {
          if (std::max(std::abs(x - cx), std::abs(y - cy)) != ring) continue;
          const auto it = grid.find(key(x, y));
          if (it == grid.end()) continue;
          for (const Vec2& q : it->second) best = std::min(best, (p - q).norm());
        }
      if (best <= static_cast<double>(ring) * cell) break;
    }
    worst = std::max(worst, best);
  }
  return worst;
}

}  // namespace

std::filesystem::path lsystem_corpus_dir() {
  return std::filesystem::path(DOCKGRAMMAR_SOURCE_DIR) / ".." / "shared" / "corpus" / "lsystems";
}

std::vector<std::string> lsystem_corpus_cases() {
  std::vector<std::string> ids;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(lsystem_corpus_dir(), error))
    if (entry.path().extension() == ".svg" && std::filesystem::exists(std::filesystem::path(entry.path()).replace_extension(".json")))
      ids.push_back(entry.path().stem().string());
  std::sort(ids.begin(), ids.end());
  return ids;
}

std::vector<Vec2> drawing_points(const SvgDrawing& drawing, double spacing) {
  std::vector<Vec2> points;
  for (const auto& element : drawing.elements)
    for (const auto& line : element.polylines) densify(line, spacing, points);
  return points;
}

double diagonal_of(const std::vector<Vec2>& points) {
  Vec2 low = points.front(), high = points.front();
  for (const Vec2& p : points) low = low.cwiseMin(p), high = high.cwiseMax(p);
  return (high - low).norm();
}

std::vector<Vec2> rederived_points(const InferredLSystem& inferred, double spacing, double units_per_svg_unit) {
  const Derivation derivation = derive(inferred.lsystem);
  const Drawing drawing = interpret(derivation.modules, turtle_options(inferred.lsystem.turtle));
  std::vector<Vec2> points;
  for (const Stroke& stroke : drawing.strokes)
    for (const auto& line : flatten_path(stroke.path, spacing * units_per_svg_unit / 2)) {
      std::vector<Vec2> svg;
      for (const Vec2& p : line)
        svg.emplace_back((inferred.start_svg.x() + p.x()) / units_per_svg_unit, (inferred.start_svg.y() - p.y()) / units_per_svg_unit);
      densify(svg, spacing, points);
    }
  return points;
}

double symmetric_hausdorff(const std::vector<Vec2>& a, const std::vector<Vec2>& b, double cell) {
  if (a.empty() || b.empty()) return std::numeric_limits<double>::infinity();
  return std::max(directed_hausdorff(a, b, cell), directed_hausdorff(b, a, cell));
}

}  // namespace dg::test
