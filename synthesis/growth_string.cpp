#include "synthesis/growth_string.h"

#include "grammar/open_lsystem.h"
#include "synthesis/segment2d.h"

#include <algorithm>

namespace dg {

namespace {

constexpr std::size_t none = static_cast<std::size_t>(-1);

// The placeholder of a stretch: a symbol no L-system text can name, its number as argument.
const std::string stretch_symbol = "<stretch>";

bool is_placeholder(const Module& module) { return module.symbol == stretch_symbol; }

std::size_t stretch_number(const Module& placeholder) { return static_cast<std::size_t>(placeholder.parameters[0]); }

bool same_pose(const TurtlePose& a, const TurtlePose& b) {
  return a.position == b.position && a.heading_deg == b.heading_deg && a.scale == b.scale;
}

// ?X stands for the segment it tests: the turtle moves past it without drawing.
void move_past_query(const Module& module, bool answered, TurtlePose& pose) {
  if (is_collision_query(module.symbol))
    pose.position += heading_vector(pose.heading_deg) * collision_query_length(module, answered, pose.scale);
}

// A kept motif copy whose outline (flattened into pieces of about 1/8 of its size) enters the grid.
DrawnMotif draw_motif(Path2d path, double id, SegmentGrid& grid) {
  DrawnMotif drawn{std::move(path), {}};
  if (drawn.path.commands.empty()) return drawn;
  Vec2 low = drawn.path.commands.front().points[0], high = low;
  add_path_bounds(drawn.path, low, high);
  const double piece = std::max((high - low).norm() / 8, 1e-9);
  for (const std::vector<Vec2>& line : flatten_path(drawn.path, piece))
    for (std::size_t i = 1; i < line.size(); ++i)
      if (line[i] != line[i - 1]) drawn.outline.push_back(grid.insert({line[i - 1], line[i], id}));
  return drawn;
}

// A visitor that keeps the elements drawn by `ids`' modules whose centre lies in the guide
// (motifs: their anchor), recording each element's module when asked.
TurtleVisitor drawing_visitor(const GrowthCanvas& canvas, const std::vector<double>& ids, DrawnElements& out,
                              std::vector<std::size_t>* segment_modules, std::vector<std::size_t>* motif_modules) {
  TurtleVisitor visitor;
  visitor.segment = [&canvas, &ids, &out, segment_modules](std::size_t k, const Vec2& from, const Vec2& to) {
    if (!point_in_polygon(0.5 * (from + to), *canvas.polygon)) return;
    out.segments.push_back(canvas.grid->insert({from, to, ids[k]}));
    if (segment_modules) segment_modules->push_back(k);
  };
  visitor.motif = [&canvas, &ids, &out, motif_modules](std::size_t k, const Path2d& motif, const TurtlePose& pose,
                                                       double size) {
    if (!point_in_polygon(pose.position, *canvas.polygon)) return;
    out.motifs.push_back(draw_motif(place_motif(motif, pose, size), ids[k], *canvas.grid));
    if (motif_modules) motif_modules->push_back(k);
  };
  return visitor;
}

}  // namespace

void DrawnElements::erase_from(SegmentGrid& grid) {
  for (std::size_t id : segments) grid.remove(id);
  for (const DrawnMotif& motif : motifs)
    for (std::size_t id : motif.outline) grid.remove(id);
  segments.clear();
  motifs.clear();
}

GrowingString::GrowingString(std::vector<Module> axiom, SeedStart start) : start_(std::move(start)) {
  modules_ = std::move(axiom);
  fresh_.assign(modules_.size(), 1);
  apply_cuts(modules_, nullptr, &fresh_);
  ids_.assign(modules_.size(), start_.element_id);
}

void GrowingString::replace(std::vector<Module>& next, std::vector<char>& fresh, const std::vector<std::size_t>& origins,
                            SegmentGrid& grid) {
  std::vector<double> ids(next.size());
  for (std::size_t k = 0; k < next.size(); ++k)
    ids[k] = fresh[k] ? assigned_id(modules_[origins[k]]).value_or(start_.element_id) : ids_[origins[k]];
  std::vector<std::size_t> present;
  for (const Module& module : next)
    if (is_placeholder(module)) present.push_back(stretch_number(module));
  std::sort(present.begin(), present.end());
  for (std::size_t number : alive_)
    if (!std::binary_search(present.begin(), present.end(), number)) {  // cut away
      Stretch& stretch = stretches_[number];
      frozen_elements_ -= stretch.drawn.count();
      stretch.drawn.erase_from(grid);
      stretch = Stretch{};
    }
  alive_ = std::move(present);
  modules_.swap(next);
  fresh_.swap(fresh);
  ids_ = std::move(ids);
}

std::vector<PendingQuery> GrowingString::interpret(const GrowthCanvas& canvas) {
  live_.erase_from(*canvas.grid);
  live_segment_modules_.clear();
  live_motif_modules_.clear();
  before_.resize(modules_.size());
  std::vector<PendingQuery> queries;
  TurtleVisitor visitor = drawing_visitor(canvas, ids_, live_, &live_segment_modules_, &live_motif_modules_);
  visitor.before = [this](std::size_t k, const TurtlePose& pose) { before_[k] = pose; };
  visitor.other = [&](std::size_t k, TurtlePose& pose) {
    const Module& module = modules_[k];
    if (is_placeholder(module)) {
      Stretch& stretch = stretches_[stretch_number(module)];
      if (!same_pose(stretch.start, pose)) redraw(stretch, pose, canvas);
      pose = stretch.end;
      return;
    }
    if (!is_query_symbol(module.symbol)) return;
    if (fresh_[k]) queries.push_back({k, pose});
    move_past_query(module, !fresh_[k], pose);
  };
  final_ = walk_turtle(modules_, *canvas.turtle, start_.pose, visitor);
  return queries;
}

void GrowingString::redraw(Stretch& stretch, const TurtlePose& pose, const GrowthCanvas& canvas) {
  frozen_elements_ -= stretch.drawn.count();
  stretch.drawn.erase_from(*canvas.grid);
  TurtleVisitor visitor = drawing_visitor(canvas, stretch.ids, stretch.drawn, nullptr, nullptr);
  visitor.other = [&stretch](std::size_t k, TurtlePose& at) { move_past_query(stretch.modules[k], true, at); };
  stretch.start = pose;
  stretch.end = walk_turtle(stretch.modules, *canvas.turtle, pose, visitor);
  frozen_elements_ += stretch.drawn.count();
}

void GrowingString::merge_into(Stretch& target, std::size_t k, std::size_t& segment_cursor, std::size_t& motif_cursor) {
  Module& module = modules_[k];
  if (is_placeholder(module)) {
    Stretch& source = stretches_[stretch_number(module)];
    std::move(source.modules.begin(), source.modules.end(), std::back_inserter(target.modules));
    target.ids.insert(target.ids.end(), source.ids.begin(), source.ids.end());
    target.drawn.segments.insert(target.drawn.segments.end(), source.drawn.segments.begin(), source.drawn.segments.end());
    std::move(source.drawn.motifs.begin(), source.drawn.motifs.end(), std::back_inserter(target.drawn.motifs));
    source = Stretch{};
    return;
  }
  target.modules.push_back(std::move(module));
  target.ids.push_back(ids_[k]);
  for (; segment_cursor < live_segment_modules_.size() && live_segment_modules_[segment_cursor] == k; ++segment_cursor) {
    target.drawn.segments.push_back(live_.segments[segment_cursor]);
    ++frozen_elements_;
  }
  for (; motif_cursor < live_motif_modules_.size() && live_motif_modules_[motif_cursor] == k; ++motif_cursor) {
    target.drawn.motifs.push_back(std::move(live_.motifs[motif_cursor]));
    ++frozen_elements_;
  }
}

std::vector<std::size_t> GrowingString::collapse(const std::function<bool(const Module&)>& growing) {
  const std::size_t n = modules_.size();
  // unit_end[k]: when module k starts a unit that cannot change (one module, or a whole branch
  // `[...]` of such modules), the index of the unit's last module; none otherwise.
  std::vector<std::size_t> unit_end(n, none);
  std::vector<std::pair<std::size_t, bool>> open;  // `[` not closed yet, and whether all inside is fixed
  for (std::size_t k = 0; k < n; ++k) {
    const Module& module = modules_[k];
    if (module.symbol == "[") {
      open.emplace_back(k, true);
      continue;
    }
    if (module.symbol == "]") {
      if (open.empty()) continue;
      const auto [at, fixed] = open.back();
      open.pop_back();
      if (fixed)
        unit_end[at] = k;
      else if (!open.empty())
        open.back().second = false;
      continue;
    }
    if (is_placeholder(module) || !fresh_[k] || !growing(module))
      unit_end[k] = k;
    else if (!open.empty())
      open.back().second = false;
  }

  std::vector<std::size_t> renumber(n, none);
  std::vector<Module> modules;
  std::vector<char> fresh;
  std::vector<double> ids;
  DrawnElements live;
  std::vector<std::size_t> live_segment_modules, live_motif_modules;
  std::size_t segment_cursor = 0, motif_cursor = 0;
  auto keep = [&](std::size_t k) {
    renumber[k] = modules.size();
    for (; segment_cursor < live_segment_modules_.size() && live_segment_modules_[segment_cursor] == k; ++segment_cursor) {
      live.segments.push_back(live_.segments[segment_cursor]);
      live_segment_modules.push_back(modules.size());
    }
    for (; motif_cursor < live_motif_modules_.size() && live_motif_modules_[motif_cursor] == k; ++motif_cursor) {
      live.motifs.push_back(std::move(live_.motifs[motif_cursor]));
      live_motif_modules.push_back(modules.size());
    }
    modules.push_back(std::move(modules_[k]));
    fresh.push_back(fresh_[k]);
    ids.push_back(ids_[k]);
  };
  for (std::size_t k = 0; k < n;) {
    if (unit_end[k] == none) {
      keep(k++);
      continue;
    }
    std::size_t last = unit_end[k];
    while (last + 1 < n && unit_end[last + 1] != none) last = unit_end[last + 1];
    if (last == k && is_placeholder(modules_[k])) {
      keep(k++);
      continue;
    }
    std::size_t number = 0, first = k;
    if (is_placeholder(modules_[k])) {  // extend the stretch that starts the run
      number = stretch_number(modules_[k]);
      first = k + 1;
    } else {
      number = stretches_.size();
      stretches_.emplace_back();
      stretches_.back().start = before_[k];
    }
    Stretch& target = stretches_[number];
    for (std::size_t m = first; m <= last; ++m) merge_into(target, m, segment_cursor, motif_cursor);
    target.end = last + 1 < n ? before_[last + 1] : final_;
    for (std::size_t m = k; m <= last; ++m) renumber[m] = modules.size();
    modules.push_back({stretch_symbol, {static_cast<double>(number)}});
    fresh.push_back(0);
    ids.push_back(start_.element_id);
    k = last + 1;
  }
  modules_ = std::move(modules);
  fresh_ = std::move(fresh);
  ids_ = std::move(ids);
  live_ = std::move(live);
  live_segment_modules_ = std::move(live_segment_modules);
  live_motif_modules_ = std::move(live_motif_modules);
  alive_.clear();
  for (const Module& module : modules_)
    if (is_placeholder(module)) alive_.push_back(stretch_number(module));
  return renumber;
}

void GrowingString::answered() { std::fill(fresh_.begin(), fresh_.end(), 0); }

void GrowingString::collect(const SegmentGrid& grid, std::vector<GridSegment>& segments,
                            std::vector<Path2d>& motifs) const {
  auto add = [&](const DrawnElements& drawn) {
    for (std::size_t id : drawn.segments) segments.push_back(grid[id]);
    for (const DrawnMotif& motif : drawn.motifs) motifs.push_back(motif.path);
  };
  for (std::size_t number : alive_) add(stretches_[number].drawn);
  add(live_);
}

}  // namespace dg
