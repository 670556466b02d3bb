#pragma once
// Progress and cancellation hook passed to long operations. The library never prints.

#include <functional>
#include <string_view>

namespace dg {

/// Called with a stage name and a fraction in [0, 1]; returns false to cancel.
/// Calls come from the thread that started the operation, never from workers.
using ProgressCallback = std::function<bool(std::string_view stage, double fraction)>;

/// Reports progress when a callback is set; throws LimitError("cancelled") when it asks to stop.
void report_progress(const ProgressCallback& progress, std::string_view stage, double fraction);

}  // namespace dg
