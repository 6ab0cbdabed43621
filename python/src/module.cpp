// The extension module dgwarp._core; the package's public API is
// python/dgwarp/__init__.py, which re-exports what is bound here.
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "dgwarp/core/version.hpp"
#include "errors.hpp"
#include "py_mesh.hpp"
#include "py_mpi.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_core, m) {
    m.doc() = "dgwarp's C++ library (import the dgwarp package, not this module)";
    m.attr("__version__") = std::string(dgwarp::version());
    m.attr("_has_mpi") = dgwarp::python::has_mpi();  // prepare(comm=...) available
    dgwarp::python::bind_errors(m);
    dgwarp::python::bind_mesh(m);
    dgwarp::python::bind_quality(m);
    dgwarp::python::bind_motion(m);
    dgwarp::python::bind_plan(m);
    dgwarp::python::bind_extras(m);
}
