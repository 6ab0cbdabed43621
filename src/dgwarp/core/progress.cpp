#include "dgwarp/core/progress.hpp"

#include <algorithm>

namespace dgwarp {

ProgressFn progress_part(const ProgressFn& progress, double from, double to) {
    if (!progress) return {};
    return [progress, from, to](double f) { progress(from + std::clamp(f, 0.0, 1.0) * (to - from)); };
}

ProgressCounter::ProgressCounter(const ProgressFn& progress, std::int64_t total)
    : progress_(progress), total_(std::max<std::int64_t>(total, 0)) {
    if (progress_) report();
}

void ProgressCounter::report() {
    std::lock_guard lock(mutex_);
    // Read under the lock: a later report sees at least the count an earlier one saw.
    const std::int64_t done = done_.load(std::memory_order_relaxed);
    if (reported_ >= 0 && done < next_.load(std::memory_order_relaxed)) return;  // reported meanwhile
    const double f = total_ > 0 ? std::min(1.0, static_cast<double>(done) / static_cast<double>(total_)) : 0.0;
    if (f <= reported_) return;
    reported_ = f;
    // A percent on, but never past the end: the add that completes the count
    // must always find a report due, whatever thread reported last.
    next_.store(std::min(total_, done + std::max<std::int64_t>(1, total_ / 100)), std::memory_order_relaxed);
    progress_(f);
}

void ProgressCounter::finish() {
    if (!progress_) return;
    std::lock_guard lock(mutex_);
    if (reported_ < 1.0) {
        reported_ = 1.0;
        next_.store(INT64_MAX, std::memory_order_relaxed);
        progress_(1.0);
    }
}

}  // namespace dgwarp
