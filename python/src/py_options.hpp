#pragma once
// Methods and their options by the names the Python API gives them: the
// CLI's flags with '_' for '-' (the table in methods/option_table.hpp).
#include <pybind11/pybind11.h>

#include <string>

#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/motion_spec.hpp"

namespace dgwarp::python {

/// The method called `name` ("dg-idw", also "dg_idw"); ValueError listing the methods otherwise.
Method method_arg(const std::string& name);

/// "moving_wins" or "static_wins"; ValueError otherwise.
SharedNodeRule shared_nodes_arg(const std::string& rule);
const char* shared_nodes_name(SharedNodeRule rule);

/// A shared_tolerance argument: a length > 0, or 0 for the default (1e-9 x
/// the mesh's diagonal); ValueError for a negative or non-finite one.
double shared_tolerance_arg(double tolerance);

/// The method options given as keyword arguments to `function` (for
/// messages). TypeError for an unknown keyword, ValueError for an option of
/// another method than `method` (as the CLI refuses it) or a value of the
/// wrong kind; ranges are checked by the library when it uses them.
MethodOptions method_options(Method method, const pybind11::kwargs& kwargs, const char* function);

/// The options of `method` in `options`, by keyword.
pybind11::dict options_dict(Method method, const MethodOptions& options);

}  // namespace dgwarp::python
