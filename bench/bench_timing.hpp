#pragma once
// Repeated timings for the benchmark programs: the median (and the fastest)
// of several runs of the same call.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
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

/// The arguments `MESH [--repeats N]` of a benchmark program: false (after
/// printing the usage) when MESH is missing; `repeats` keeps its default
/// unless given.
inline bool mesh_and_repeats(int argc, char** argv, std::string& mesh, int& repeats) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s MESH [--repeats N]\n", argv[0]);
        return false;
    }
    mesh = argv[1];
    for (int i = 2; i + 1 < argc; ++i)
        if (std::string(argv[i]) == "--repeats") repeats = std::atoi(argv[i + 1]);
    return true;
}

}  // namespace dgwarp::bench
