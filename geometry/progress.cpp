#include "geometry/progress.h"

#include "geometry/errors.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <string>

namespace dg {

void report_progress(const ProgressCallback& progress, std::string_view stage, double fraction) {
  if (progress && !progress(stage, fraction)) throw LimitError("cancelled during " + std::string(stage));
}

void parallel_for_reporting(std::size_t count, const ProgressCallback& progress, std::string_view stage,
                            const std::function<void(std::size_t)>& body) {
  // Four items per worker: enough to balance uneven items, few enough to report often.
  const auto batch = static_cast<std::size_t>(4 * std::max(1, tbb::this_task_arena::max_concurrency()));
  for (std::size_t first = 0; first < count; first += batch) {
    report_progress(progress, stage, static_cast<double>(first) / static_cast<double>(count));
    tbb::parallel_for(first, std::min(first + batch, count), [&](std::size_t i) { body(i); });
  }
}

}  // namespace dg
