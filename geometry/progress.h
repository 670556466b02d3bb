#pragma once
// Progress and cancellation hook passed to long operations. The library never prints.

#include <cstddef>
#include <functional>
#include <string_view>

namespace dg {

/// Called with a stage name and a fraction in [0, 1]; returns false to cancel.
/// Calls come from the thread that started the operation, never from workers.
using ProgressCallback = std::function<bool(std::string_view stage, double fraction)>;

/// Reports progress when a callback is set; throws LimitError("cancelled") when it asks to stop.
void report_progress(const ProgressCallback& progress, std::string_view stage, double fraction);

/// Runs body(i) for i in [0, count) on the worker threads, in batches of a few items per worker;
/// before each batch the calling thread reports the fraction of items done under `stage`. The
/// caller reports 1 when its stage is over. Items must be independent (any order, any thread).
void parallel_for_reporting(std::size_t count, const ProgressCallback& progress, std::string_view stage,
                            const std::function<void(std::size_t)>& body);

}  // namespace dg
