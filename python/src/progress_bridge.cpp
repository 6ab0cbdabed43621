#include "progress_bridge.hpp"

namespace py = pybind11;

namespace dgwarp::python {

namespace {

/// Whether the calling thread is Python's main thread, the only one in which
/// Python runs signal handlers (PyErr_CheckSignals does nothing elsewhere).
bool in_main_thread() {
    static const unsigned long main_ident =
        py::module_::import("threading").attr("main_thread")().attr("ident").cast<unsigned long>();
    return PyThread_get_thread_ident() == main_ident;
}

}  // namespace

ProgressBridge::ProgressBridge(py::object callback) : callback_(std::move(callback)) {
    if (callback_.is_none()) {
        // No callback: the library still reports, so that Ctrl-C (a signal
        // handler that raises, such as SIGINT's KeyboardInterrupt) stops a long
        // call within about a percent of it rather than at its end. Python runs
        // handlers in its main thread only, so only that thread's reports check,
        // taking the GIL at most every 20 ms (uncontended then), so that a
        // millisecond step costs nothing more (Python handles a signal that
        // came during a call anyway when the call returns).
        if (!in_main_thread()) return;
        const auto caller = std::this_thread::get_id();
        next_check_ = Clock::now() + check_interval;
        function_ = [this, caller](double) {
            if (stopped_.load(std::memory_order_acquire)) throw Stop();
            if (std::this_thread::get_id() != caller) return;  // a worker thread: the caller checks
            const auto now = Clock::now();
            if (now < next_check_) return;
            next_check_ = now + check_interval;
            py::gil_scoped_acquire gil;
            if (PyErr_CheckSignals() == 0) return;
            try {
                throw py::error_already_set();
            } catch (py::error_already_set&) {
                error_ = std::current_exception();
                stopped_.store(true, std::memory_order_release);
            }
            throw Stop();
        };
        return;
    }
    if (!PyCallable_Check(callback_.ptr()))
        throw py::type_error("progress must be a callable taking the fraction done (a float), got " +
                             py::str(py::type::of(callback_)).cast<std::string>());
    function_ = [this](double fraction) {
        // The callback raised already: stop as soon as the library reports again.
        if (stopped_.load(std::memory_order_acquire)) throw Stop();
        py::gil_scoped_acquire gil;
        try {
            callback_(fraction);
        } catch (py::error_already_set&) {
            error_ = std::current_exception();
            stopped_.store(true, std::memory_order_release);
            throw Stop();
        }
    };
}

}  // namespace dgwarp::python
