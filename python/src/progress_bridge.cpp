#include "progress_bridge.hpp"

namespace py = pybind11;

namespace dgwarp::python {

ProgressBridge::ProgressBridge(py::object callback) : callback_(std::move(callback)) {
    if (callback_.is_none()) return;
    if (!PyCallable_Check(callback_.ptr()))
        throw py::type_error("progress must be a callable taking the fraction done (a float), got " +
                             py::str(py::type::of(callback_)).cast<std::string>());
    function_ = [this](double fraction) {
        if (error_) throw Stop();  // the callback raised already: stop as soon as the library reports again
        py::gil_scoped_acquire gil;
        try {
            callback_(fraction);
        } catch (py::error_already_set&) {
            error_ = std::current_exception();
            throw Stop();
        }
    };
}

}  // namespace dgwarp::python
