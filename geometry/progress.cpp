#include "geometry/progress.h"

#include "geometry/errors.h"

#include <string>

namespace dg {

void report_progress(const ProgressCallback& progress, std::string_view stage, double fraction) {
  if (progress && !progress(stage, fraction)) throw LimitError("cancelled during " + std::string(stage));
}

}  // namespace dg
