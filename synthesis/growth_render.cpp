#include "synthesis/growth_render.h"

namespace dg {

namespace {

Path2d polyline(const std::vector<Vec2>& points, bool closed) {
  Path2d path;
  for (std::size_t i = 0; i < points.size(); ++i)
    path.commands.push_back({i == 0 ? PathCommand::Type::Move : PathCommand::Type::Line,
                             {points[i], Vec2::Zero(), Vec2::Zero()}});
  if (closed) path.commands.push_back({PathCommand::Type::Close, {Vec2::Zero(), Vec2::Zero(), Vec2::Zero()}});
  return path;
}

}  // namespace

Drawing growth_drawing(const GrowthScene& scene, const GrowthResult& result) {
  Drawing drawing;
  const Rgba8 guide_color{160, 160, 160, 255}, link_color{60, 110, 220, 255}, motif_color{40, 130, 60, 255};
  for (const Guide& guide : scene.guides) drawing.strokes.push_back({polyline(guide.polygon, true), 0, guide_color, 0.5});
  for (const GuideLink& link : scene.links) {
    const std::vector<Vec2>& polygon = scene.guides[link.from_guide].polygon;
    drawing.strokes.push_back(
        {polyline({polygon[link.from_edge], polygon[(link.from_edge + 1) % polygon.size()]}, false), 0, link_color, 1.0});
  }
  for (const GuideGrowth& guide : result.guides) {
    for (const GridSegment& segment : guide.segments) drawing.strokes.push_back({polyline({segment.a, segment.b}, false), 0});
    for (const Path2d& motif : guide.motifs) drawing.strokes.push_back({motif, 0, motif_color, 1.0});
  }
  return drawing;
}

}  // namespace dg
