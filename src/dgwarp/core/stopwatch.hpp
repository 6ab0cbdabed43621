#pragma once
// Wall-clock timing of algorithm stages, reported to callers (benchmarks, logs).
#include <chrono>

namespace dgwarp {

using Clock = std::chrono::steady_clock;

/// Seconds elapsed since `start`.
inline double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace dgwarp
