#pragma once
// The parts of the module, each bound by its own file.
#include <pybind11/pybind11.h>

namespace dgwarp::python {

void bind_quality(pybind11::module_& m);  // py_quality.cpp
void bind_motion(pybind11::module_& m);   // py_motion.cpp
void bind_plan(pybind11::module_& m);     // py_plan.cpp
void bind_extras(pybind11::module_& m);   // py_extras.cpp: cases, threads, untangle

}  // namespace dgwarp::python
