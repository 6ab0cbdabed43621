#pragma once
// Wall-clock timing of algorithm stages and of a program's phases, reported
// to callers (benchmarks, logs, the CLI's reports).
#include <chrono>

namespace dgwarp {

using Clock = std::chrono::steady_clock;

/// Seconds elapsed since `start`.
inline double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Times consecutive phases.
class Stopwatch {
public:
    /// Seconds since construction or the last lap(), and restarts.
    double lap() {
        const Clock::time_point now = Clock::now();
        const double s = std::chrono::duration<double>(now - start_).count();
        start_ = now;
        return s;
    }

private:
    Clock::time_point start_ = Clock::now();
};

}  // namespace dgwarp
