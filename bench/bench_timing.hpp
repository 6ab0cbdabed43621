#pragma once
// Repeated timings for the benchmark programs: the median (and the fastest)
// of several runs of the same call.
#include <algorithm>
#include <vector>

#include "dgwarp/core/stopwatch.hpp"

namespace dgwarp::bench {

struct Timing {
    double median = 0, min = 0;  // seconds
};

/// Runs f `repeats` (at least 1) times and returns the median and fastest wall times.
template <class F>
Timing time_repeats(int repeats, F&& f) {
    std::vector<double> t;
    for (int r = 0; r < repeats; ++r) {
        const auto t0 = Clock::now();
        f();
        t.push_back(seconds_since(t0));
    }
    std::sort(t.begin(), t.end());
    return {t[t.size() / 2], t[0]};
}

/// The median of time_repeats.
template <class F>
double median_seconds(int repeats, F&& f) {
    return time_repeats(repeats, f).median;
}

}  // namespace dgwarp::bench
