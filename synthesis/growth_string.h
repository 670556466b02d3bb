#pragma once
// One seed's string during guided growth (growth.h), kept short so that a step costs what its
// growing parts cost. A run of modules that no later step can rewrite (copied unchanged by a
// step, or made by one but without production and not a query) is collapsed into one
// placeholder module, a *stretch*, that keeps those modules, the turtle poses before and after
// them and the elements they drew. The rewriter copies a placeholder like any module without
// production; the turtle jumps over it when it meets it at the pose it was drawn from, and
// redraws it only when that pose changed. A `cut` that erases a placeholder erases its elements.

#include "grammar/module.h"
#include "synthesis/growth_queries.h"
#include "synthesis/path2d.h"
#include "synthesis/segment_grid.h"
#include "synthesis/turtle.h"

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace dg {

/// A kept motif copy and the grid entries of its outline (motifs block queries like segments).
struct DrawnMotif {
  Path2d path;
  std::vector<std::size_t> outline;
};

/// Kept elements: grid ids of segments and motif copies.
struct DrawnElements {
  std::vector<std::size_t> segments;
  std::vector<DrawnMotif> motifs;

  /// Elements held (segments and motifs).
  std::size_t count() const { return segments.size() + motifs.size(); }
  /// Removes every grid entry from `grid` and forgets the elements.
  void erase_from(SegmentGrid& grid);
};

/// Where a string draws: the guide polygon (an element is kept when its centre lies inside),
/// the turtle settings and the guide's element grid.
struct GrowthCanvas {
  const std::vector<Vec2>* polygon = nullptr;
  const TurtleOptions* turtle = nullptr;
  SegmentGrid* grid = nullptr;
};

/// A fresh query module at string index `module`, seen at `pose`.
struct PendingQuery {
  std::size_t module = 0;
  TurtlePose pose;
};

/// One seed's growing string with the elements it drew.
class GrowingString {
 public:
  /// A new string: `axiom` (cuts applied), all of it fresh, grown from `start`.
  GrowingString(std::vector<Module> axiom, SeedStart start);

  /// The live string (placeholders included). The rewriter takes it (copied modules are moved
  /// out); queries write their answers into it.
  std::vector<Module>& modules() { return modules_; }
  const std::vector<Module>& modules() const { return modules_; }
  /// Per module: 1 when the last step made it (or it is in the axiom) and it is not answered yet.
  const std::vector<char>& fresh() const { return fresh_; }
  const SeedStart& start() const { return start_; }

  /// Takes the result of a rewrite step of modules() with cuts applied (`origins` and `fresh` as
  /// Rewriter::step gives them, filtered alike). Stretches the step dropped lose their elements
  /// from `grid`. A new module's element id is its parent's idin when the parent is an answered
  /// ?XS or ?XSI (assigned_id), else the seed's id.
  void replace(std::vector<Module>& next, std::vector<char>& fresh, const std::vector<std::size_t>& origins,
               SegmentGrid& grid);

  /// Draws the string from the seed's pose into `canvas` (elements of live modules are drawn
  /// again, stretches only when their start pose changed) and returns its fresh query modules
  /// in string order with the poses they are seen at.
  std::vector<PendingQuery> interpret(const GrowthCanvas& canvas);

  /// Collapses every maximal run of modules that cannot change any more (`growing(m)` says
  /// whether a fresh module m still can: a query, or a symbol with productions) into one
  /// stretch; call after interpret(). Returns for every old index its new one (runs map to
  /// their placeholder).
  std::vector<std::size_t> collapse(const std::function<bool(const Module&)>& growing);

  /// Marks the fresh queries answered.
  void answered();

  /// Kept elements (segments and motifs) of the string.
  std::size_t elements() const { return frozen_elements_ + live_.count(); }

  /// Appends the kept segments (from `grid`) and motif copies, stretches first.
  void collect(const SegmentGrid& grid, std::vector<GridSegment>& segments, std::vector<Path2d>& motifs) const;

 private:
  struct Stretch {
    std::vector<Module> modules;
    std::vector<double> ids;
    TurtlePose start, end;
    DrawnElements drawn;
  };

  void redraw(Stretch& stretch, const TurtlePose& pose, const GrowthCanvas& canvas);
  void merge_into(Stretch& target, std::size_t k, std::size_t& segment_cursor, std::size_t& motif_cursor);

  SeedStart start_;
  std::vector<Module> modules_;
  std::vector<char> fresh_;
  std::vector<double> ids_;              // element id of what each module draws
  std::vector<TurtlePose> before_;       // pose before each module in the last interpret()
  TurtlePose final_;                     // pose after the last module
  DrawnElements live_;                   // elements of modules that are not in a stretch
  std::vector<std::size_t> live_segment_modules_, live_motif_modules_;  // their modules
  std::vector<Stretch> stretches_;       // by placeholder number; erased ones are empty
  std::vector<std::size_t> alive_;       // placeholder numbers in the string
  std::size_t frozen_elements_ = 0;      // elements held by stretches
};

}  // namespace dg
