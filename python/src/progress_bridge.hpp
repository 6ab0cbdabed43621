#pragma once
// A Python progress callback as the library's ProgressFn (core/progress.hpp).
// The library runs with the GIL released; each report takes the GIL to call
// the callback (reports may come from worker threads, one at a time, about
// once per percent). An exception raised by the callback stops the library
// call and is raised again to the caller.
//
// Without a callback, reports from the calling thread, when it is Python's
// main thread, run Python's signal handlers (PyErr_CheckSignals), so that
// Ctrl-C stops a long read, prepare or deform with KeyboardInterrupt as it
// would stop Python code.
#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <exception>
#include <thread>
#include <utility>

#include "dgwarp/core/progress.hpp"

namespace dgwarp::python {

class ProgressBridge {
public:
    /// `callback`: None (no reports; signals are still handled) or a callable taking one float.
    explicit ProgressBridge(pybind11::object callback);

    /// The function to pass to the library (empty for None outside the main thread).
    const ProgressFn& function() const { return function_; }

    /// Runs `f` with the GIL released; raises again what the callback raised.
    template <class F>
    void run(F&& f) {
        try {
            pybind11::gil_scoped_release release;
            std::forward<F>(f)();
        } catch (const Stop&) {
        }
        if (error_) std::rethrow_exception(error_);
    }

private:
    /// Thrown through the library when the callback raised.
    struct Stop : std::exception {
        const char* what() const noexcept override { return "the progress callback raised an exception"; }
    };

    pybind11::object callback_;
    std::exception_ptr error_;  // what the callback raised (a pybind11::error_already_set)
    std::atomic<bool> stopped_{false};  // error_ is set: other threads stop at their next report
    using Clock = std::chrono::steady_clock;
    static constexpr std::chrono::milliseconds check_interval{20};
    Clock::time_point next_check_;  // without a callback: when to check for signals next (the caller's thread only)
    ProgressFn function_;
};

}  // namespace dgwarp::python
