#pragma once
// Wall-clock timing of the CLI's phases.
#include <chrono>

namespace dgwarp::cli {

class Stopwatch {
public:
    Stopwatch() : start_(std::chrono::steady_clock::now()) {}
    /// Seconds since construction or the last lap(), and restarts.
    double lap() {
        const auto now = std::chrono::steady_clock::now();
        const double s = std::chrono::duration<double>(now - start_).count();
        start_ = now;
        return s;
    }

private:
    std::chrono::steady_clock::time_point start_;
};

}  // namespace dgwarp::cli
