#pragma once
// Progress of long library calls (reading a large mesh, locating nodes in the
// Delaunay graph, RBF factorisation and evaluation, IDW steps). The library
// never prints: a caller that wants a progress display passes a ProgressFn as
// the last argument of those calls; an empty one (the default) costs nothing.
#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>

namespace dgwarp {

/// Receives how far a call is, as a fraction in [0, 1]. Within one call the
/// fractions never decrease and the last one is 1 (when the call succeeds).
/// It may be called from worker threads (one call at a time), so an
/// implementation that touches state shared with other threads must be
/// thread-safe. Calls come per block of work (about 1% of it, at least a few
/// thousand nodes or ~1 MB of text), never per node. An empty function means
/// no reporting.
using ProgressFn = std::function<void(double fraction)>;

/// `progress` mapped to the part [from, to] of a larger call: the returned
/// function reports from + f (to - from). Empty when `progress` is empty.
ProgressFn progress_part(const ProgressFn& progress, double from, double to);

/// Counts finished items of a loop over `total` items that may run on
/// several threads, and reports done / total to a ProgressFn: at most about
/// once per percent, with nondecreasing fractions. Adding is one atomic
/// addition (a lock only when a report is due), so loops may add per item
/// of a few microseconds' work; reports nothing when the function is empty
/// (then add() is a single branch).
class ProgressCounter {
public:
    /// Reports 0 (the start). `progress` must outlive the counter.
    ProgressCounter(const ProgressFn& progress, std::int64_t total);
    ProgressCounter(const ProgressCounter&) = delete;
    ProgressCounter& operator=(const ProgressCounter&) = delete;

    /// Adds `done` finished items (thread-safe); reports when the fraction
    /// has grown by a percent or more since the last report.
    void add(std::int64_t done) {
        if (progress_ && done_.fetch_add(done, std::memory_order_relaxed) + done >= next_.load(std::memory_order_relaxed))
            report();
    }
    /// Reports 1 unless already reported (all items done, or stopping early).
    void finish();

private:
    void report();

    const ProgressFn& progress_;
    std::int64_t total_;
    std::atomic<std::int64_t> done_{0};
    std::atomic<std::int64_t> next_{0};  // items at which the next report is due
    std::mutex mutex_;                    // held while reporting, so reports come in order
    double reported_ = -1;                // the last fraction reported
};

}  // namespace dgwarp
